"""A colleague named as the one who needs the thing ("Mark needs my ruler for a student on his
course, could you take it over", "Wang could use my stapler for a client meeting"): that
colleague is whom it goes to, so an outsider said after "for" in the same message is what the
thing is for (a student Mark teaches, a meeting with a client), never its recipient; read as
the recipient, the request was asked about as if the thing were for someone outside. Only a
need said of a colleague counts: "my ruler is for a student, take it to reception" names
nobody who needs it and is still asked about."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.core import english

_NEEDS = english.words("need_verbs")
_PHRASES = tuple(
    tuple(p.split()) for p in (*english.entries("need_phrases"), *english.entries("modal_wants"))
)


def colleague_needs(msg: Message, piece: Piece) -> bool:
    """Whether ``piece`` or one before it names a colleague (no possessive) with a need verb
    right after the name ("Mark needs ...", "Wang is after ...", "Wang could use ...")."""
    for said in (p.lexed for p in msg.pieces if p.start <= piece.start):
        words = [t.word for t in said.tokens]
        for m in said.mentions:
            if m.kind != "person" or m.possessive:
                continue
            if words[m.end : m.end + 1] and words[m.end] in _NEEDS:
                return True
            if any(tuple(words[m.end : m.end + len(p)]) == p for p in _PHRASES):
                return True
    return False
