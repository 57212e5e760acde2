"""Problem: "is the key encoder working? the guest says his card won't open the door": after a
question about a facility's state, a piece that asks for nothing (no request wording, no
question mark) reports what is wrong; it is context for the question, answered in words,
never a request of its own (the guest's card is nobody's errand)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms


def problem(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.need or acts.question is not None:
        return None
    asked = [
        p
        for p in msg.pieces
        if p.end <= piece.start
        and p.acts.question == "info"
        and not p.acts.request
        and terms.named(p.lexed, "facility")
    ]
    if not asked:
        return None
    return Finding("statement", piece, "a problem reported beside a question, context only")
