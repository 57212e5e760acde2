"""A message that says it only informs: "fridge temp light is on amber again, just so you
know", "fyi the scanner's making that noise". The tag is told, and so is a sentence beside
it that asks nothing (no request wording, no question): both are noted in words and nothing
moves. A request beside the tag is still a request ("fyi I'm in at 9, can you print my
rota?")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_TAGS = tuple(tuple(entry.split()) for entry in english.entries("fyi_tags"))
# the tags that close a piece ("btw" is a filler where it opens one, "btw can you ...")
_CLOSING = tuple(tuple(entry.split()) for entry in english.entries("fyi_closing_tags"))
_FILLERS = frozenset({"oh", "and", "but", "ok", "okay", "btw", "also", "thanks", "cheers"})


def _tag(words: list[str]) -> tuple[str, ...] | None:
    """The tag a piece opens with, if any ("fyi", "just so you know"), or closes with ("...
    start at 9 this year btw")."""
    w = [x for x in words if x not in _FILLERS]
    opening = next((t for t in _TAGS if tuple(w[: len(t)]) == t), None)
    if opening is not None:
        return opening
    return next((t for t in _CLOSING if len(words) > len(t) and tuple(words[-len(t) :]) == t), None)


def _only_a_tag(piece: Piece) -> bool:
    w = [x for x in piece.words if x not in _FILLERS]
    tag = _tag(piece.words)
    return tag is not None and len(w) == len(tag)


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    return piece.asks or acts.request or acts.imperative or acts.question is not None


def fyi(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del terms, requester
    if _only_a_tag(piece):
        return Finding("statement", piece, "a tag that only informs")
    tagged = any(_tag(p.words) is not None for p in msg.pieces)
    if not tagged or _asks(piece) or any(_asks(p) for p in msg.pieces if not _only_a_tag(p)):
        return None
    return Finding("statement", piece, "told for information, context only")
