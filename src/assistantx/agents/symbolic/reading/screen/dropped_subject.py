"""A sentence of chat that drops its subject "I" ("been at the machine all morning", "been
stuck in S4 since 8"): the speaker's own state, so it gets its "I've" back before the pieces
are judged and is read as the statement it is, never as a request naming a facility ("heat a
tea at the machine")."""

from __future__ import annotations

import re

from assistantx.core.task_schema import Evidence

# "been" opening a sentence (the message's start, or after a stop): "(I've) been ..."
_BEEN = re.compile(r"(^|[.!?;]\s*|\n\s*)(been)\b(?!\s+(?:you|u|told|asked)\b)", re.IGNORECASE)


def subject_restored(text: str) -> tuple[str, list[Evidence]]:
    """``text`` with "I've" before a sentence that opens with "been"."""
    found: list[Evidence] = []

    def restore(match: re.Match[str]) -> str:
        found.append(Evidence(words=match.group(2), meaning="I've been (the speaker)"))
        return f"{match.group(1)}I've {match.group(2)}"

    return _BEEN.sub(restore, text), found
