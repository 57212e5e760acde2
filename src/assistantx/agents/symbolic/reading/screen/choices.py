"""Choices offered with a question: "where do we keep the clay, workshop store or dry store?",
"is the battery charged, yes or no?": the part after the comma lists what the answer may be
("A or B", no verb of its own), so it belongs to the question before it and asks nothing by
itself; it is dropped with the question. After a request ("bring me some clay, workshop store
or dry store") the same words say where to fetch from and stay with the request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language

_OR = frozenset({"or"})
# what stands between the question and its choices ("..., A or B?", "... - A or B?")
_JOINING = frozenset({",", "-", "–", "—", ":", "?"})


def choices(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    words = piece.words
    if not set(words) & _OR or piece.acts.request or piece.acts.imperative:
        return None
    if any(m.kind == "cue" for m in piece.lexed.mentions):
        return None  # a task word of its own ("..., print it or copy it")
    if any(
        language.is_finite_verb(w) or language.is_present_participle(w) for w in _unnamed(piece)
    ):
        return None  # a clause of its own, not a list of answers
    before = [p for p in msg.pieces if p.end <= piece.start]
    if not before or before[-1].acts.question != "info":
        return None
    if msg.text[before[-1].end : piece.start].strip() not in _JOINING:
        return None  # only the choices said right after the question, with its own mark
    return Finding("question", piece, "the choices offered with the question before it")


def _unnamed(piece: Piece) -> list[str]:
    """The piece's words outside the names of the office's things, people and places (so
    "records" of "records office" is no verb)."""
    named = {
        n
        for m in piece.lexed.mentions
        if m.kind in ("item", "person", "facility", "place")
        for n in range(m.start, m.end)
    }
    return [t.word for n, t in enumerate(piece.lexed.tokens) if n not in named]
