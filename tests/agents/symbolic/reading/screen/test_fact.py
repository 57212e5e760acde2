"""Fact: a person away, here or somewhere; an item's condition; the requester's own item out
of use. Each is a hint for the plan."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.fact import fact
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms

Read = Callable[[str], Message]


def hint_of(terms: Terms, message: Read, text: str) -> tuple[str, str, str, str | None] | None:
    msg = message(text)
    found = fact(terms, msg, msg.pieces[0], "lee")
    if found is None or found.hint is None:
        return None
    h = found.hint
    return (h.kind, h.person, h.value, h.item_type)


def test_a_person_away_here_or_at_a_place(terms: Terms, message: Read) -> None:
    assert hint_of(terms, message, "Wang is away") == ("availability", "wang", "away", None)
    assert hint_of(terms, message, "Zhang is in the meeting room") == (
        "location",
        "zhang",
        "meeting_room",
        None,
    )


def test_an_items_condition(terms: Terms, message: Read) -> None:
    assert hint_of(terms, message, "Zhang's stapler is broken") == (
        "condition",
        "zhang",
        "broken",
        "stapler",
    )


def test_the_requesters_own_item_out_of_use(terms: Terms, message: Read) -> None:
    assert hint_of(terms, message, "I can't find my stapler") == (
        "condition",
        "lee",
        "missing",
        "stapler",
    )


def test_a_request_is_no_fact(terms: Terms, message: Read) -> None:
    assert hint_of(terms, message, "bring me Wang's stapler") is None
    assert hint_of(terms, message, "Wang needs a stapler") is None
