"""What someone else wants to know, told beside a request or alone: "does anyone have a tide
book I could borrow? a passenger wants to know high water at the pier", "anyone got a
calculator I could borrow? a visitor wants to know the coffee prices", "my intern asked about
water damage". A subject, then "wants to know" / "asked about" / "is asking about" (english
data ``need_to_know``), then a topic: the topic's words (the water, the coffee) are what the
question is about, never a thing asked for, so the piece is context and the request is the
rest of the message. Before, the topic's thing was read as wanted ("not offered here: water",
or a coffee made).

A reported request ("Zhang wants to know if someone could bring him a coffee") is read for its
ask by ``reading.reported_request``, and one about where a thing is or who has it ("Zhang
wants to know where the stapler is") by the rules of whereabouts: both are left to them. The
speaker's own wish to know a topic ("I want to know the coffee prices") asks for no thing
either (before, a coffee was made); "I'd like to know if you could ..." is a request, left."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_PHRASES: tuple[tuple[str, ...], ...] = tuple(
    sorted((tuple(p.split()) for p in english.entries("need_to_know")), key=len, reverse=True)
)
# The one who wants to know is never the one spoken to ("do you want to know ...")
_NOT_OTHERS = frozenset({"you", "u", "ya", "do", "does", "did"})
# What a reported request or a question of whereabouts opens with (left to their rules)
_LEFT_TO_OTHERS = frozenset({"if", "whether", "where", "who", "whose", "which"})
_OPENERS = frozenset({"and", "but", "oh", "also", "btw", "fyi", "so", "because", "cos", "as"})


def need_to_know(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """A piece that tells what someone wants to know: context, nothing to do."""
    words = piece.words
    start = 0
    while start < len(words) and words[start] in _OPENERS:
        start += 1
    for at in range(start + 1, len(words)):
        phrase = next((p for p in _PHRASES if tuple(words[at : at + len(p)]) == p), None)
        if phrase is None:
            continue
        subject = words[start:at]
        if set(subject) & _NOT_OTHERS or len(subject) > 4:
            return None
        after = words[at + len(phrase) :]
        if not after or after[0] in _LEFT_TO_OTHERS:
            return None
        return Finding("statement", piece, "what someone wants to know: context only")
    return None
