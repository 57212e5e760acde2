"""Asides that join a second request to a first: "print my file, and while you're at it grab
me some gloves", "... and if you can bring me an ice bucket". The aside says only that the
second part is asked as well; it names nothing, so its words ("it" in "at it") are no part of
either request, and the second part is a request of its own when an errand's or service's
verb follows the aside. The phrases are English data (``request_asides``)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.listed_parts import listed_as_needs
from assistantx.agents.symbolic.reading.phrase_index import by_first_word, without_phrases
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_ASIDES: tuple[tuple[str, ...], ...] = tuple(
    sorted((tuple(p.split()) for p in english.entries("request_asides")), key=len, reverse=True)
)


_ASIDES_AT = by_first_word(_ASIDES)


def aside_length(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> int:
    """How many mentions from ``mentions[n]`` on are one aside phrase (0: none), counted only
    when a task's verb follows it ("while you're at it grab ...")."""
    if n >= len(mentions):
        return 0
    start = mentions[n].start
    for phrase in _ASIDES:
        end = start + len(phrase)
        if tuple(t.word for t in tokens[start:end]) != phrase:
            continue
        inside = sum(1 for m in mentions[n:] if m.start < end)
        if n + inside < len(mentions) and mentions[n + inside].kind == "cue":
            return inside
    return 0


def without_asides(words: Sequence[str]) -> list[str]:
    """``words`` without the aside phrases in them: "and a coffee for me while you are at it"
    is no statement for the "you are" of its aside, which tells nothing of the world."""
    return without_phrases(words, _ASIDES_AT)


_alternatives = english.alternation  # the lists' phrases as one regex alternation


# "Two things: ...", "A couple of quick things - ...": a count of what follows, then a colon
# or a dash, at the start of the message or of a sentence
_ANNOUNCED = re.compile(
    rf"(?:^|(?<=[.!?])\s+)(?:{_alternatives('list_counts')})\s+"
    rf"(?:(?:{_alternatives('list_degrees')})\s+)*(?:{_alternatives('list_nouns')})"
    r"(?:\s+(?:please|pls|for\s+you))?\s*(?::|\s[-–—]+)\s*",
    re.IGNORECASE,
)


# the end of the listed parts: their sentence's end
_SENTENCE_END = re.compile(r"[.!?](?:\s|$)")


def announced_list(text: str) -> str:
    """ "Two things: take my torch to Ida, and I need a coffee": the opening count names no
    item and asks nothing; it is dropped, so what follows is read as if said alone (never a
    statement about "things"). The parts in note form after it ("2 things: my report
    printed, and Wang's stapler") are each the speaker's need (``listed_as_needs``)."""
    out: list[str] = []
    at = 0
    for m in _ANNOUNCED.finditer(text):
        if m.start() < at:
            continue
        out.append(text[at : m.start()] + (" " if m.start() else ""))
        end = _SENTENCE_END.search(text, m.end())
        stop = end.start() if end is not None else len(text)
        out.append(listed_as_needs(text[m.end() : stop]))
        at = stop
    return "".join(out) + text[at:]
