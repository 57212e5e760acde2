"""A note to keep ("note this down: ..."), and what follows it in the same message."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.note import note
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Judge, Read


def test_a_note_and_the_sentence_after_it_are_kept_in_words(terms: Terms, message: Read) -> None:
    msg = message("Note this down. Wang is away next week.")
    found = [note(terms, msg, p, "lee") for p in msg.pieces]
    assert [f.verdict if f else None for f in found] == ["note", "note"]
    assert found[0] is not None and found[0].message == "Noted."


def test_a_request_after_a_note_is_read_as_one(terms: Terms, message: Read) -> None:
    msg = message("Note this down. Bring me a pen.")
    assert note(terms, msg, msg.pieces[0], "lee") is not None
    assert note(terms, msg, msg.pieces[1], "lee") is None


def test_a_request_is_no_note(judged: Judge) -> None:
    assert judged(note, "bring me a pen", "lee") is None
