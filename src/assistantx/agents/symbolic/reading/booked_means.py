"""A send-out booked by its means: "book a courier for my parcel", "can you arrange a courier
for my contract to Leeds". Where the office has a service that sends things out by that means
(the courier desk's "send by courier"), booking the means for a thing is that service asked
for the thing: said as "send <thing> by <means>", which the reader reads as the send-out (and
asks where to when no place is said). A booking of anything else ("book me the meeting room
for Friday") is left as said: nothing here books rooms or slots, and it is declined."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.core.office import Office
from assistantx.core.wording import by_means

_WORD = r"[^\W\d_][\w'’-]*"
_BOOKED = re.compile(
    r"\b(?:book|arrange|organise|organize|call)\s+(?:me\s+|us\s+)?(?:a|an|the)\s+"
    rf"(?P<means>{_WORD})\s+for\s+"
    rf"(?P<thing>(?:my|our|this|these|the|that|those)(?:\s+{_WORD}){{1,3}}?)"
    r"(?=\s*(?:to\b|please\b|pls\b|[?.!,;]|$))",
    re.IGNORECASE,
)


def send_out_means(office: Office) -> frozenset[str]:
    """The means the office's send-out services send by ("courier", "fax")."""
    out: set[str] = set()
    for op in office.operations:
        if not op.sends_out:
            continue
        out.update(w.lower() for w in means_words(op.name))
        said = by_means(op).removeprefix("by ").strip()
        if said:
            out.add(said.lower())
    return frozenset(out)


def booked_means(text: str, means: frozenset[str]) -> str:
    """``text`` with "book a <means> for <thing>" said as "send <thing> by <means>" where
    ``means`` (``send_out_means``) has it."""
    if not means:
        return text

    def said(m: re.Match[str]) -> str:
        if m.group("means").lower() not in means:
            return m.group(0)
        return f"send {m.group('thing')} by {m.group('means')}"

    return _BOOKED.sub(said, text)
