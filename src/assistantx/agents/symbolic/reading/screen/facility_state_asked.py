"""A facility's state asked with the verb left out: "laminator working today?", "the scrap
cage open yet?", "laminator still jammed?". The question mark and a word of state right after
the facility's name ask how it is, as "is the laminator working today?" does; answered in
words from what the office file says, and nothing moves (never a request for its service,
never a withdrawal)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.elsewhere import state_said
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_FAULTS = tuple(tuple(p.split()) for p in english.entries("facility_faults"))
# How a working facility is said to be, besides the faults and conditions of english.yaml.
_WORKING = (
    ("working",),
    ("ok",),
    ("okay",),
    ("open",),
    ("running",),
    ("up",),
    ("free",),
    ("fixed",),
    ("back",),
    ("on",),
    ("behaving",),
    ("any", "better"),
)
_OPENERS = frozenset({"the", "is", "our", "that", "so"})
_STILL = frozenset({"still", "now", "yet"})


def facility_state_asked(
    terms: Terms, msg: Message, piece: Piece, requester: str
) -> Finding | None:
    if not piece.asks or piece.acts.request:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in _OPENERS:
            return None
        k += 1
    if k >= len(mentions) or mentions[k].kind != "facility" or len(mentions[k].ids) != 1:
        return None
    rest = [t.word for t in tokens[mentions[k].end :]]
    rest = rest[1:] if rest[:1] and rest[0] in _STILL else rest
    state = state_said(rest)
    said = (*_WORKING, *_FAULTS, *terms.en.conditions)
    if not state or not any(starts_with(state, 0, s) for s in said):
        return None
    return Finding(
        "question",
        piece,
        "a question about a facility's state, answered in words",
        message=in_service(terms, mentions[k].ids[0]),
    )


def in_service(terms: Terms, facility_id: str) -> str:
    """The answer about a facility's state: what the office file says, and no more."""
    f = terms.office.facility(facility_id)
    where = terms.office.location(f.location).name
    return (
        f"As far as I know the {f.name} at the {where} is in service, but I can't check it "
        "from here."
    )
