"""Slang for taking, in a request for leave to have a thing: "can I nick Robin's mute for the
Ravel?", "could I pinch a pen off Zhang" ask to borrow it, as people say it in British
English. The speaker asks for themselves, so it is a borrowing, and a borrowing leaves its
owner only with the owner's own yes, asked in their chat. The slang verb is written as
"borrow" before the message is read. Told to the robot ("nick Robin's mute", "pinch Min's
mug for me"), the words still take someone's things and are declined (``destructive``)."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import phrases_pattern
from assistantx.core.task_schema import Evidence

_SLANG = phrases_pattern("taking_slang")
# "can I", "could i just", "may we", "mind if I", "ok if I": leave asked for the speaker
_LEAVE = re.compile(
    rf"\b(?P<ask>(?:can|could|may|might)\s+(?:i|we)|(?:mind|ok|okay|alright)\s+if\s+(?:i|we))"
    rf"(?P<just>\s+(?:just|quickly))?\s+(?P<verb>{_SLANG})\b",
    re.IGNORECASE,
)


def asked_leave(text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a slang verb of taking, in a request for leave, written "borrow"."""
    found: list[Evidence] = []

    def borrow(match: re.Match[str]) -> str:
        found.append(Evidence(words=match.group(0), meaning="asks to borrow"))
        return f"{match.group('ask')}{match.group('just') or ''} borrow"

    return _LEAVE.sub(borrow, text), found
