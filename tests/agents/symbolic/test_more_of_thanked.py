""" "more" / "a bit more" / "some more" / "another one" after thanks for a thing asks for more
of that thing ("thanks for the paper earlier! could you bring a bit more": "there is no bit
more in this office" was answered). The thanks alone still moves nothing, and a request that
names its own thing keeps it."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        (
            "thanks for the paper earlier! could u bring a bit more, ours has run out again",
            "transfer",
            "paper",
        ),
        ("thanks for the paper, can you bring me some more?", "transfer", "paper"),
        ("Thank you for the paper. Could I have a little more please", "transfer", "paper"),
        ("thanks for the coffee! can I have another one", "produce", "coffee"),
        ("thanks so much for the coffee earlier, could I get some more", "produce", "coffee"),
        ("cheers for the coffee, another one please?", "produce", "coffee"),
    ],
)
def test_more_after_thanks_is_more_of_the_thing(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "lee")], frame


@pytest.mark.parametrize(
    "text", ["thanks for the coffee earlier", "thanks for the paper!", "thank you for the coffee"]
)
def test_thanks_alone_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame


def test_a_request_naming_its_thing_keeps_it() -> None:
    frame = _frame("thanks for the coffee! could you bring me some paper")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "paper")], frame


def test_more_with_nothing_thanked_is_asked() -> None:
    frame = _frame("could you bring me a bit more")
    assert frame.tasks == [] and frame.question is not None, frame
