"""A spare asked for with no thing named is a spare of the thing the message names (fix135c,
class 5): "my pen's run out... any spares around?" was answered "I don't know of any spares
around". "Spare" is a spare of something: the one item the rest of the message names, so the
ask is answered for that item and met with "Shall I ...?"; with nothing named, which thing is
asked back (reading/screen/spare_of.py, in the question rule)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    ["my pen's run out... any spares around?", "my pen has run out, got any spares?"],
)
def test_a_spare_of_the_thing_said_is_offered(text: str) -> None:
    frame = _default(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and "pen" in frame.question, frame
    assert frame.question.endswith("Shall I bring you one?"), frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("my highlighter's dried up... any spares around?", "highlighter"),
        ("notepad's full, any spares going?", "stationery cupboard"),
    ],
)
def test_the_same_in_another_office(text: str, said: str) -> None:
    frame = _harbour(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and said in frame.question, frame
    assert "Shall I" in frame.question, frame


def test_a_spare_of_nothing_named_asks_which() -> None:
    frame = _default("any spares around?")
    assert not frame.tasks and frame.decline is not None, frame
    assert frame.decline.startswith("Which item do you need a spare of?"), frame


def test_a_request_for_one_still_moves() -> None:
    frame = _default("my pen's run out, can you bring me one")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("pen", "lee")], frame
