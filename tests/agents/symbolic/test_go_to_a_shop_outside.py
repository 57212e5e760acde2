"""Blind rounds 43-48, class J5: "go to the Starbucks across the street and get me a
frappuccino" is an errand outside the office, declined in words, though "go" and "to" are
lead-in words of requests ("go print it") and so no verb the screen saw told to the robot:
"go" and a word of going opening the request tell it to go (``outside_place._told_to_go``),
and the place said outside declines it; never a coffee made at the office's machine. "go to
the kitchen and get me a coffee" (the office's own place) is read as before (on
``helpers.notary_office``; the rounds' own offices and sentences were never read)."""

from __future__ import annotations

import pytest

from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    "text",
    [
        "go to the Starbucks across the street and get me a frappuccino",
        "go to the cafe across the road and get me a latte",
        "can you go down to the Tesco on the high street and get me some milk",
        "could you go over to the Costa round the corner and grab me a coffee",
        "please go to the Pret in town and pick me up a latte",
    ],
)
def test_going_to_a_shop_outside_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "outside the office" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "go to the kitchen and get me a coffee",
        "go and make me a coffee",
        "make me a coffee",
        "go to the coffee machine and get me a latte",
    ],
)
def test_the_offices_own_coffee_is_read_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")], frame


def test_the_speakers_own_going_declines_nothing() -> None:
    frame = _frame("I need to go to the cafe across the street, can you make me a coffee")
    assert frame.decline is None or "outside the office" not in frame.decline, frame
