"""A second part said short and brought back: "take my stapler to Zhang, and a coffee on the
way back". The way back is the robot's return to the one who asked, so a thing picked up on it
is the speaker's, as "and on the way back get a coffee" already is; read alone, the short part
would take its recipient from the errand before it (the coffee to Zhang). So where the short
part names an item of the office and says for whom it is neither by "for" nor "to", the speaker
is written in ("a coffee for me on the way back"). A part that says whom ("and a coffee for
Chen on the way back"), or a way that is not back ("and a coffee on the way"), is read as
before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Evidence

_SHORT_PART = re.compile(
    r"(?P<part>\b(?:and|plus|also)\s+(?:a|an|some|one|the)\s+(?P<thing>[^\W\d_]+(?:\s+[^\W\d_]+){0,2}))"
    r"(?P<back>\s+on\s+(?:the|your|ur)\s+way\s+back\b)",
    re.IGNORECASE,
)
_WHOSE = frozenset({"for", "to", "me", "us"})


def brought_back(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with "for me" written into a short part picked up on the way back."""
    found: list[Evidence] = []

    def mine(match: re.Match[str]) -> str:
        thing = match.group("thing").lower()
        if set(thing.split()) & _WHOSE or not any(
            m.kind == "item" for m in terms.lex.read(thing).mentions
        ):
            return match.group(0)  # says whom, or names nothing of the office
        said = f"{match.group('part')} for me{match.group('back')}"
        found.append(Evidence(words=match.group(0).strip(), meaning=said.strip()))
        return said

    return _SHORT_PART.sub(mine, text), found
