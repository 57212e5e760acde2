"""A hedge set off inside a sentence: "Holly, I think, has a measuring cylinder - could I
borrow it?". The speaker's doubt between commas (or dashes) is no part of what is said: left
in, it cut the subject from its verb, so Holly was no longer read as the one who has the
cylinder and anyone's was borrowed. It is taken out before the message is read; a hedge that
is the sentence's own verb ("I think Holly has one") is left as written."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import phrases_pattern
from assistantx.core.task_schema import Evidence

_HEDGES = phrases_pattern("parenthetical_hedges")
# set off on both sides: ", I think," / " - I think - "
_SET_OFF = re.compile(rf"\s*(?:,|\s[-–—])\s*(?:{_HEDGES})\s*(?:,|[-–—]\s)\s*", re.IGNORECASE)


def without_hedges(text: str) -> tuple[str, list[Evidence]]:
    """``text`` with each hedge set off inside a sentence taken out."""
    found: list[Evidence] = []

    def drop(match: re.Match[str]) -> str:
        found.append(Evidence(words=match.group(0).strip(), meaning="a hedge, no part of it"))
        return " "

    return _SET_OFF.sub(drop, text), found
