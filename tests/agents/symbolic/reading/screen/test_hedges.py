"""A hedge set off inside a sentence is no part of it; one that is the sentence's verb stays."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.hedges import without_hedges
from assistantx.core.office import load_office
from helpers.reading import frame_reader


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("Zhang, I think, has a stapler", "Zhang has a stapler"),
        ("Zhang - I believe - has a stapler", "Zhang has a stapler"),
        ("Zhang, apparently, has a stapler", "Zhang has a stapler"),
    ],
)
def test_a_hedge_set_off_is_taken_out(text: str, read: str) -> None:
    out, evidence = without_hedges(text)
    assert out == read
    assert [e.meaning for e in evidence] == ["a hedge, no part of it"]


@pytest.mark.parametrize(
    "text", ["I think Zhang has a stapler", "Zhang has one I think", "maybe bring me a pen"]
)
def test_a_hedge_not_set_off_is_left(text: str) -> None:
    assert without_hedges(text) == (text, [])


def test_the_owner_behind_the_hedge_is_asked() -> None:
    """Blind round 28's class: "Holly, I think, has a measuring cylinder - could I borrow
    it?" borrowed anyone's cylinder; Holly's is the one meant."""
    frame = frame_reader(load_office, "liu")("Zhang, I think, has a stapler - could I borrow it?")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "zhang", "liu")]
