"""A verb and its particle joined by a hyphen after a determiner name a thing or an event,
not the verb asked, when a noun follows: "a puck for *the warm-up* drill", "the sign-off
sheet". Split into two words the verb was read as work asked of the office (an
office that heats things read "the warm-up drill" as heating, and asked what "the warm up"
was, in eight generated tasks of blind round 193). The compound is written as one word (the
noun English writes it as: "warmup"), which no stage reads as a verb. A compound that is one
of the office's own words, or with no noun after it ("take the print-out to Mao": the
printout made), keeps its reading."""

from __future__ import annotations

import re
from collections.abc import Container

from assistantx.core import english, language

_DETERMINERS = "|".join(sorted(english.words("object_starts") | {"a", "an", "the"}))
_PARTICLES = "up|off|out|in|down|over|on|back|through|away"
_COMPOUND = re.compile(
    rf"\b(?P<det>{_DETERMINERS})\s+(?P<verb>[^\W\d_]+)-(?P<particle>{_PARTICLES})"
    r"\s+(?P<noun>[^\W\d_]+)",
    re.IGNORECASE,
)


def hyphened_nouns(text: str, office_words: Container[str]) -> str:
    """``text`` with each "<determiner> <verb>-<particle>" that is none of the office's
    words written as one noun ("the warm-up drill" → "the warmup drill")."""

    def join(m: re.Match[str]) -> str:
        verb, particle = m.group("verb"), m.group("particle")
        if (verb + particle).lower() in office_words:
            return m.group(0)
        if not language.is_noun(m.group("noun")) or m.group("noun").lower() in office_words:
            return m.group(0)  # "the print-out to Mao", "the print-out paper"
        return f"{m.group('det')} {verb}{particle} {m.group('noun')}"

    return _COMPOUND.sub(join, text)
