"""A note to keep ("note this down: the tape ran out"): answered in words, never an errand."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms


def note(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "note this down: the tape ran out", "mark this down: ...": a note to keep, answered
    in words; a later piece of the same message is part of it unless it asks for
    something ("Note this down. Ida is away next week.")."""
    said = piece.acts.note
    noting = msg.noting is not None and piece.start >= msg.noting
    if said is None and not (noting and not piece.acts.request):
        return None
    if said is not None:
        msg.noting = piece.start
        if piece.acts.note_asks:
            return None  # "please note I need a ruler": a request, read as one
    return Finding("note", piece, "a note to keep, not a request", message="Noted.")
