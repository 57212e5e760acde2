"""Said beside a question, how it is meant: "who's got a ruler? just curious, not urgent".
Curiosity ("just curious", "only wondering", "out of curiosity") says the question asks no
errand, so it is answered in words with no "Shall I bring you one?"; an unhurried aside ("not
urgent", "no rush") says nothing to do of its own, so it is no request to puzzle over either.
Beside a request ("bring me a ruler, no rush") the request is read as ever."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms

# The meaning of a finding of curiosity: the answer beside it offers nothing (``answer``).
CURIOUS = "curiosity: the question asks no errand"

_CURIOSITY = (
    ("curious",),
    ("wondering",),
    ("asking",),
    ("out", "of", "curiosity"),
    ("curiosity",),
)
_UNHURRIED = (
    ("not", "urgent"),
    ("no", "rush"),
    ("no", "hurry"),
    ("not", "important"),
    ("nothing", "urgent"),
)
# Words that only soften the phrase ("I'm just curious", "purely out of curiosity tho").
_SOFTENERS = frozenset(
    {"i", "im", "am", "was", "just", "only", "purely", "really", "tho", "though", "btw", "lol"}
)


def _said(words: list[str], phrases: tuple[tuple[str, ...], ...]) -> bool:
    said = tuple(w for w in words if w not in _SOFTENERS)
    return said in phrases


def curious(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.question is not None or piece.acts.request:
        return None
    if not any(p.acts.question is not None for p in msg.pieces if p is not piece):
        return None  # "just curious" alone, or beside a request: read as before
    if _said(piece.words, _CURIOSITY):
        return Finding("statement", piece, CURIOUS)
    if _said(piece.words, _UNHURRIED):
        return Finding("statement", piece, "an aside: no hurry")
    return None
