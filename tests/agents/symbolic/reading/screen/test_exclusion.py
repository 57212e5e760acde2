"""Exclusion: "not from Wang though": that person's item is kept out by a hint."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.exclusion import exclusion
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Judge, Read


def test_not_from_a_person_keeps_their_item_of_the_message_out(terms: Terms, message: Read) -> None:
    msg = message("bring me a stapler, not from Wang though")
    found = exclusion(terms, msg, msg.pieces[1], "lee")
    assert found is not None and found.hint is not None
    assert (found.hint.kind, found.hint.person, found.hint.item_type, found.hint.value) == (
        "condition",
        "wang",
        "stapler",
        "not wanted",
    )
    assert found.meaning == "not Wang Fang's stapler"


def test_an_exclusion_needs_one_person_and_an_item(judged: Judge) -> None:
    assert judged(exclusion, "not now", "lee") is None
    assert judged(exclusion, "bring me a stapler", "lee") is None
