"""Whom a message opens by addressing: "Otto, could the robot bring me your ruler?", "Otto -
can I borrow your ruler?", "hey Otto, ...". A colleague named first (after a greeting at
most), then a comma, a dash or a colon, is spoken to; "your" before an item in that message
is theirs (the owner is asked in their own chat, as for any owned item). Without such an
opening "your" is read as before (nobody's in particular)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token

_GREETINGS = frozenset({"hey", "hi", "hello", "oi", "yo", "dear", "morning", "afternoon"})
_ADDRESS_MARKS = frozenset(",:-\u2013\u2014")
_YOUR = "your"


def addressed_person(
    tokens: Sequence[Token], mentions: Sequence[Mention], gaps: Sequence[str]
) -> str | None:
    """The one colleague the message opens by addressing, or None."""
    first = next((m for m in mentions if m.kind == "person"), None)
    if first is None or first.possessive or len(set(first.ids)) != 1:
        return None
    if any(t.word not in _GREETINGS for t in tokens[: first.start]):
        return None
    if first.end >= len(tokens) or first.end >= len(gaps):
        return None
    if not set(gaps[first.end]) & _ADDRESS_MARKS:
        return None
    return first.ids[0]


def yours_addressed(tokens: Sequence[Token], item: Mention, addressed: str | None) -> str | None:
    """The owner of ``item`` when "your" stands right before it (or before one describing
    word: "your steel ruler") in a message addressed to a colleague."""
    if addressed is None:
        return None
    for k in (item.start - 1, item.start - 2):
        if k < 0:
            return None
        if tokens[k].word == _YOUR and not tokens[k].possessive:
            return addressed
        if tokens[k].possessive or tokens[k].after_pause:
            return None
    return None
