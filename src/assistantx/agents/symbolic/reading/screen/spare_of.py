"""A spare asked for with no thing named: "my pen's run out... any spares around?", "any
spare going?". "Spare" is a spare *of* something: the thing the message names before it
(the pen that ran out), so the question asks for one of that thing, not about a thing called
"spares"; with nothing named, which thing is asked back."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms

_SPARE = frozenset({"spare", "spares"})
# what may stand around "spares" in such an ask: who has one, and where it might be
_ASKING = frozenset(
    {
        "any",
        "anyone",
        "anybody",
        "got",
        "have",
        "has",
        "are",
        "is",
        "there",
        "you",
        "u",
        "some",
        "a",
        "do",
        "does",
        "we",
    }
)
_WHERE = frozenset({"around", "about", "going", "anywhere", "here", "kicking", "lying", "knocking"})


def spares_only(piece: Piece) -> bool:
    """Whether the piece asks for a spare naming no thing: "any spares around?", "got any
    spare going?"."""
    words = piece.words
    return bool(set(words) & _SPARE) and all(w in _SPARE | _ASKING | _WHERE for w in words)


def spare_of(terms: Terms, msg: Message, piece: Piece) -> list[str]:
    """The items the rest of the message names, that such a spare is one of; a piece that
    names a colleague ("Ginger's charger is dead") tells of their thing, no spare of the
    speaker's, and is left to the rules that read it."""
    return sorted(
        {
            i
            for p in msg.pieces
            if p is not piece and not terms.named(p.lexed, "person")
            for i in terms.named(p.lexed, "item")
        }
    )
