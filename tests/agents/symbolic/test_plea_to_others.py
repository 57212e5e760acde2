"""A plea to unknown others ("whoever keeps nicking the oat milk from the staff fridge, please
stop", "can people stop ...", "to whoever keeps ...: stop it") asks nothing of the assistant:
answered in words, nothing moves (blind rounds 61-62's class: a question "What should I do,
with which item, and for whom?" ended failed; "can people stop taking X" fetched X). A
request to the assistant beside "whoever" is read as before."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    "text",
    [
        "whoever keeps nicking the oat milk from the staff fridge, please stop",
        "whoever keeps using Olive's olive oil, please stop",
        "whoever keeps nicking the olive oil from the fridge, please stop it",
        "to whoever keeps taking my stapler: please stop",
        "whoever keeps moving my stapler, stop it",
        "can people stop taking the oat milk from the fridge",
        "Everyone please stop leaving mugs by the kettle",
        "could people please stop eating the snacks in the kit room",
    ],
)
def test_a_plea_to_others_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "don't know who" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can you ask whoever has the oat milk to bring it back", "oat_milk"),
        ("whoever has Olive's seal, no rush, but could you bring me some oat milk", "oat_milk"),
    ],
)
def test_a_request_to_the_assistant_is_read_as_before(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None or "don't know who" not in frame.decline, frame
    assert [t.item for t in frame.tasks] == [item], frame


def test_a_bare_stop_alone_is_still_asked_about() -> None:
    frame = _frame("please stop")
    assert frame.question is not None, frame
