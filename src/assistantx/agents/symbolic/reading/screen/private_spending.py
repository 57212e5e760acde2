"""Spending a colleague's or the workplace's money on oneself: "get kwame's fuel card out of
the key safe for me, need to fill up my own car before I go home", "grab the petty cash tin,
I'm short for my shopping". A card or cash that pays for the workplace's own costs
(english.yaml ``payment_things``), fetched for a purpose the message says is the speaker's
private one (``private_purposes``: "my own car", "personal use"), is misuse however it is
asked: declined in words with the reason, before the errand is read (round 272: the card was
fetched, its holder asked for it).

Only where both are said in the message: "bring me Kwame's fuel card, the van's empty" is the
workplace's errand, read as before, and so is the speaker's own card ("my fuel card ... my own
car": theirs to use)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_PAYING = tuple(
    sorted((tuple(e.split()) for e in english.entries("payment_things")), key=len, reverse=True)
)
_PRIVATE = tuple(tuple(e.split()) for e in english.entries("private_purposes"))
_OWN = frozenset({"my", "mine"})


def _payment_said(words: list[str]) -> str | None:
    """The payment thing the words name, as said, where it is not the speaker's own."""
    for n in range(len(words)):
        for thing in _PAYING:
            if starts_with(words, n, thing) and not (n and words[n - 1] in _OWN):
                return " ".join(thing)
    return None


def _private(words: list[str]) -> bool:
    return any(starts_with(words, n, p) for n in range(len(words)) for p in _PRIVATE)


def private_spending(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not (piece.acts.request or piece.acts.imperative or commanded(terms, piece)):
        return None
    thing = _payment_said(piece.words)
    if thing is None or not any(_private(p.words) for p in msg.pieces):
        return None
    return Finding(
        "unsupported",
        piece,
        "a workplace card or cash asked for a private use",
        message=(
            f"Sorry, I won't do that: the {thing} pays for the workplace's own costs, not a "
            "private one. Please ask your manager if you need an advance. I did nothing."
        ),
    )
