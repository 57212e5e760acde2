"""A thing asked to go where someone lives or to a street: "drop Frank's drawings round to
the applicant's house on Elm Road", "take my parcel to 12 Mill Lane". The robot works inside
the office; such a place is outside it, so the request is declined in words, with the reason,
before anything in it is read as an errand (read as an errand, the drawings were fetched from
Frank and brought to the requester). Where the office has a service that sends things out
(a courier, the post) and the message names it, the place is that service's destination and
is read as before; a place of the office ("to Hal's desk", "to the post room") is no home."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.outsider import sends_out
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_HOMES = english.words("home_nouns")
_STREETS = english.words("street_words")
_TO = frozenset({"to", "round", "over", "at"})
_REACH = 5  # "to the new applicant's house": the words between "to" and the place


def _outside_at(piece: Piece, office_at: set[int]) -> bool:
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    for n, w in enumerate(words):
        if w != "to":
            continue
        for k in range(n + 1, min(n + 1 + _REACH, len(words))):
            if k in office_at:
                break  # "to Hal's desk", "to the post room": the office's own place
            if words[k] in _HOMES and k > n + 1:
                return True  # "to the applicant's house", "to her flat"
            if words[k] in _STREETS and tokens[k - 1].text[:1].isupper() and k > n + 1:
                return True  # "to 12 Mill Lane"
    return False


def outside_place(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del requester
    if not (piece.acts.request or piece.acts.imperative) or sends_out(terms, msg):
        return None
    office_at = {
        k
        for m in piece.lexed.mentions
        if m.kind in ("place", "facility", "person", "group")
        for k in range(m.start, m.end)
        if not m.possessive
    }
    if not _outside_at(piece, office_at):
        return None
    return Finding(
        "unsupported",
        piece,
        "a place outside the office",
        message=(
            "Sorry, I can't take things outside the office: I only go to people and places "
            "here. If someone here should have it, tell me who. I did nothing."
        ),
    )
