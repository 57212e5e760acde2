"""Condition: says when, never what to do; a need that may come later is not for now."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.condition import condition
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Judge, Read


def test_an_if_clause_is_a_condition_with_what_it_names_as_context(judged: Judge) -> None:
    found = judged(condition, "if Wang isn't using her stapler, could you bring it over?", "lee")
    assert found is not None and found.verdict == "condition"
    assert found.message == "Noted; I'll keep it in mind."
    assert "person:wang" in found.context


def test_a_need_that_may_come_later_is_not_for_now(judged: Judge) -> None:
    found = judged(condition, "I might need a stapler later", "lee")
    assert found is not None
    assert found.meaning == "a need that may come later, not a request for now"
    assert found.message == "Noted. Tell me when you need it and I'll bring it then."


def test_a_plain_request_is_no_condition(judged: Judge) -> None:
    assert judged(condition, "bring me a stapler", "lee") is None


def test_a_possible_new_one_is_of_the_item_an_earlier_piece_named(
    terms: Terms, message: Read
) -> None:
    msg = message("my stapler is broken, I might need a new one")
    found = condition(terms, msg, msg.pieces[1], "lee")
    assert found is not None and found.offer == "bring me a stapler"
    assert found.context == ("stapler|",)
    alone = message("I might need a new one")  # no item named before it: nothing to offer
    found = condition(terms, alone, alone.pieces[0], "lee")
    assert found is None or not found.offer


@pytest.mark.parametrize(
    "text",
    [
        # round 207's class: the adverb after "could I" is politeness, not doubt
        "could i possibly borrow Zhang's stapler for the handouts?",
        "could I perhaps borrow a stapler",
        "may I possibly borrow a pen",
    ],
)
def test_a_polite_possibly_after_could_i_is_a_request_for_now(judged: Judge, text: str) -> None:
    assert judged(condition, text, "lee") is None


@pytest.mark.parametrize("text", ["I might possibly need a stapler", "maybe I'll need a pen"])
def test_a_possible_need_said_as_such_is_still_for_later(judged: Judge, text: str) -> None:
    found = judged(condition, text, "lee")
    assert (
        found is not None and found.meaning == "a need that may come later, not a request for now"
    )
