"""Destructive: declined with what the office offers instead."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.destructive import destructive
from reading.screen._judge import Judge


def test_throwing_away_is_declined(judged: Judge) -> None:
    found = judged(destructive, "could you throw away Wang's stapler", "lee")
    assert found is not None and found.meaning == "destructive: throw away"
    assert found.message.startswith("Sorry, I won't throw away anything")
    assert "What I can do here:" in found.message


def test_a_destructive_verb_in_a_later_part_is_found(judged: Judge) -> None:
    found = judged(destructive, "bring me a pen and hide Wang's stapler", "lee")
    assert found is not None and found.meaning == "destructive: hide"


def test_a_request_is_not_destructive(judged: Judge) -> None:
    assert judged(destructive, "bring me Wang's stapler", "lee") is None
