"""A moment asked for ("give me a min to find another", "gimme a sec", "hang on a tick") asks
nothing of the robot, even where a colleague is called Min (blind round 55's class; its office
and sentences were never read): told in words, nothing moved. Beside a request the request
stands; a thing after the while is still asked for; the name as a name is still a person."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")


@pytest.mark.parametrize(
    "text",
    [
        "give me a min to find another",
        "gimme a sec",
        "give me a moment",
        "hang on a tick",
        "give me a min",
        "give me a sec to find my mask",
        "give me a minute to look for another",
        "just a mo",
        "oh hold on a sec",
        "give me two mins",
    ],
)
def test_a_moment_asked_is_told_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "min" not in frame.decline.lower(), frame


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("give Min a mask", "mask", "min"),
        ("give me a second pair of clippers", "clippers", "gwen"),
        ("just a mo, bring me a ruler", "ruler", "gwen"),
        ("give me a min, then bring me the rack", "rack", "gwen"),
    ],
)
def test_a_request_beside_or_after_it_stands(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)], frame


def test_a_name_after_give_me_is_still_its_owner() -> None:
    frame = _frame("give me Min's calculator")
    assert [(t.item, t.owner) for t in frame.tasks] == [("calculator", "min")], frame
