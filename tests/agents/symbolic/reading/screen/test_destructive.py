"""Destructive: declined with what the office offers instead."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.destructive import destructive
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms

Read = Callable[[str], Message]


def test_throwing_away_is_declined(terms: Terms, message: Read) -> None:
    msg = message("could you throw away Wang's stapler")
    found = destructive(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.meaning == "destructive: throw away"
    assert found.message.startswith("Sorry, I won't throw away anything")
    assert "What I can do here:" in found.message


def test_a_destructive_verb_in_a_later_part_is_found(terms: Terms, message: Read) -> None:
    msg = message("bring me a pen and hide Wang's stapler")
    found = destructive(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.meaning == "destructive: hide"


def test_a_request_is_not_destructive(terms: Terms, message: Read) -> None:
    msg = message("bring me Wang's stapler")
    assert destructive(terms, msg, msg.pieces[0], "lee") is None
