"""Who is dealing with a fault, told: "Wang is on it", "Zhang's looking at it", "Gao has it in
hand", "Hu is sorting it". A colleague and one of the set phrases of dealing with "it" (and
nothing after but a time or an aside) asks the assistant for nothing: answered in words.

Read before the facts, where "is on" was read as a whereabouts ("Wang is on leave"); "can you
get Wang to look at it?" is asked of the assistant and read as a request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_DEALING = tuple(
    sorted((tuple(p.split()) for p in english.entries("dealing_with_it")), key=lambda p: -len(p))
)
_TAILS = english.words("state_tails") | english.words("remark_tails")


def dealing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del msg, requester
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    if not mentions or mentions[0].kind != "person" or mentions[0].start != 0:
        return None
    who = mentions[0]
    words = [t.word for t in tokens]
    # "Zhang's looking at it": the possessive is "Zhang is", read with what follows
    at = who.end
    said = next((d for d in _DEALING if starts_with(words, at, d)), None)
    if said is None or not all(w in _TAILS for w in words[at + len(said) :]):
        return None
    name = terms.office.person(who.id).name if len(who.ids) == 1 else who.text
    return Finding(
        "statement",
        piece,
        f"who is dealing with it: {name}",
        message=f"Good to know {name} is dealing with it.",
    )
