"""An owner's leave for a colleague to keep their thing: "Wang can keep my stapler for now",
"..., Drew can hang on to them", "Wang is welcome to hold on to it till Friday". A colleague
(not "you") said to be allowed to keep, hang on to or hold on to the speaker's thing (or "it",
"them") asks the assistant for nothing: it is told, answered in words, and nothing moves.

"Wang can have my stapler" is left to the other rules (it may ask for the thing to be given),
and so is any piece asked ("can Wang keep my stapler?") or with more after the thing than
words of time."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_ALLOWED = tuple(tuple(p.split()) for p in english.entries("leave_modals"))
_KEEPING = tuple(
    sorted((tuple(p.split()) for p in english.entries("keeping_verbs")), key=lambda p: -len(p))
)
_OWN = frozenset({"my", "our"})
_HELD = frozenset({"it", "them", "that", "those", "this", "these"})
_TAILS = english.words("state_tails") | english.words("remark_tails") | english.words("leave_tails")


def owner_leave(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del msg, requester
    if piece.asks:
        return None  # "can Wang keep my stapler?": asked
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    if not mentions or mentions[0].kind != "person" or mentions[0].possessive:
        return None
    who = mentions[0]
    if len(who.ids) != 1 or who.start != 0:
        return None
    at = who.end
    allowed = next((a for a in _ALLOWED if starts_with(words, at, a)), None)
    if allowed is None:
        return None
    at += len(allowed)
    keeping = next((k for k in _KEEPING if starts_with(words, at, k)), None)
    if keeping is None:
        return None
    at += len(keeping)
    if at < len(words) and words[at] in _HELD:
        at += 1  # "hang on to it"
    elif at < len(words) and words[at] in _OWN:
        things = [m for m in mentions if m.kind == "item" and m.start > at]
        if not things:
            return None
        at = things[0].end  # "keep my stapler"
    else:
        return None
    if not all(w in _TAILS for w in words[at:]):
        return None  # more said after the thing: read by the other rules
    name = terms.office.person(who.id).name
    return Finding(
        "statement",
        piece,
        f"an owner's leave for {name} to keep their thing, asking nothing",
        message=f"Noted: {name} can keep it.",
    )
