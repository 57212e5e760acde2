"""One request, two recipients (blind round 57-58's class; the round's own offices and
sentences were never read): "make me a coffee and bring Tam one too", "tea for me and one for
Bron", "brew two: one for me, one for Kit" ask two of the same kind, one each. "one", "one
too" and "another" stand for the kind just named; an operation's verb said as the request
("brew for me") names what it makes where the office has exactly one operation asked so."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


def _made(text: str) -> set[tuple[str, str | None, str]]:
    return {(t.kind, t.item, t.recipient) for t in _frame(text).tasks}


@pytest.mark.parametrize(
    ("text", "item", "other"),
    [
        ("make me a coffee and bring Tam one too", "coffee", "tam"),
        ("tea for me and one for Bron pls", "tea", "bronwen"),
        ("make me a tea and make Kit one too", "tea", "kit"),
        ("make me a tea and another for Kit", "tea", "kit"),
        ("make me a tea, then another for Kit", "tea", "kit"),
        ("brew two: one for me, one for Kit", "tea", "kit"),
        ("brew for me and one for Bron", "tea", "bronwen"),
        ("could you get me a coffee and get Dr N one too", "coffee", "nadia"),
    ],
)
def test_each_gets_one(text: str, item: str, other: str) -> None:
    assert _made(text) == {("produce", item, "ravi"), ("produce", item, other)}, _frame(text)


def test_one_more_fetched_thing_is_anyones() -> None:
    frame = _frame("bring me a pen and bring Kit one too")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "pen", None, "ravi"),
        ("transfer", "pen", None, "kit"),
    ], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("brew me one", {("produce", "tea", "ravi")}),
        ("could you brew for Kit", {("produce", "tea", "kit")}),
        # "it" is the same drink, taken on to Kit
        ("bring me a coffee and take it to Kit", {("produce", "coffee", "kit")}),
        ("make a tea for Kit", {("produce", "tea", "kit")}),
    ],
)
def test_one_thing_stays_one(text: str, expected: set[tuple[str, str, str]]) -> None:
    assert _made(text) == expected, _frame(text)
