"""Condition: says when, never what to do; a need that may come later is not for now."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.condition import condition
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms

Read = Callable[[str], Message]


def test_an_if_clause_is_a_condition_with_what_it_names_as_context(
    terms: Terms, message: Read
) -> None:
    msg = message("if Wang isn't using her stapler, could you bring it over?")
    found = condition(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.verdict == "condition"
    assert found.message == "Noted; I'll keep it in mind."
    assert "person:wang" in found.context


def test_a_need_that_may_come_later_is_not_for_now(terms: Terms, message: Read) -> None:
    msg = message("I might need a stapler later")
    found = condition(terms, msg, msg.pieces[0], "lee")
    assert found is not None
    assert found.meaning == "a need that may come later, not a request for now"
    assert found.message == "Noted. Tell me when you need it and I'll bring it then."


def test_a_plain_request_is_no_condition(terms: Terms, message: Read) -> None:
    msg = message("bring me a stapler")
    assert condition(terms, msg, msg.pieces[0], "lee") is None
