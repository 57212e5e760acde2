"""A verb and its particle joined by a hyphen after a determiner name a thing or an event,
not the verb asked, when a noun follows: "a puck for *the warm-up* drill", "the sign-off
sheet". Split into two words the verb was read as work asked of the office (an
office that heats things read "the warm-up drill" as heating, and asked what "the warm up"
was, in eight generated tasks of blind round 193). The compound is written as one word (the
noun English writes it as: "warmup"), which no stage reads as a verb. A compound that is one
of the office's own words, or with no noun after it ("take the print-out to Mao": the
printout made), keeps its reading.

Such a compound opening a clause as its subject ("Walk-in forgot theirs, can you fetch me a
harness?", "drop-in visitor needs a pen") is a noun too: a verb hyphened to its particle is no
imperative, and read as one the request was declined as the verb ("I can't walk", blind round
256). Only where what follows is no object of a verb (a determiner or a pronoun: "pick-up my
parcel" is the verb written with a hyphen)."""

from __future__ import annotations

import re
from collections.abc import Container

from assistantx.core import english, language

_DETERMINERS = "|".join(sorted(english.words("object_starts") | {"a", "an", "the"}))
_PARTICLES = "up|off|out|in|down|over|on|back|through|away|by"
_COMPOUND = re.compile(
    rf"\b(?P<det>{_DETERMINERS})\s+(?P<verb>[^\W\d_]+)-(?P<particle>{_PARTICLES})"
    r"\s+(?P<noun>[^\W\d_]+)",
    re.IGNORECASE,
)


# A compound opening the text or a clause, and the word after it ("Walk-in forgot ...")
_OPENING = re.compile(
    rf"(?P<lead>^|[.!?;,:\n]\s*)(?P<verb>[^\W\d_]+)-(?P<particle>{_PARTICLES})"
    r"\s+(?P<next>[^\W\d_]+)",
    re.IGNORECASE,
)
# What opens a verb's object after an imperative written with a hyphen ("pick-up *my* parcel")
_OBJECT_OPENERS = (
    english.words("object_starts")
    | english.words("object_pronouns")
    | frozenset({"it", "them", "me", "us", "him", "one", "some", "any"})
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

    def subject(m: re.Match[str]) -> str:
        verb, particle, nxt = m.group("verb"), m.group("particle"), m.group("next")
        if (verb + particle).lower() in office_words:
            return m.group(0)  # "check-in" where the office calls its till so
        if nxt.lower() in _OBJECT_OPENERS or not language.verb_lemmas(verb.lower()):
            return m.group(0)  # "pick-up my parcel": the verb, its object after it
        return f"{m.group('lead')}{verb}{particle} {nxt}"

    return _OPENING.sub(subject, _COMPOUND.sub(join, text))
