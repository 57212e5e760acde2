"""A thing said again by "one" with words that describe it: "the cup needs washing, bring me
a *clean* one", "this ruler is bent, get me a *straight* one", "my pen's dead, a *working*
one please"; a thing said as a pair the same way ("tore my gloves, need a *fresh* pair").

English leaves the noun out after describing words and puts "one" in its place; the words
between the article and "one" describe the thing, they name no other thing. Read as "another
one" (the rewrite of a thing stated before, ``screen.rewrites``), the request is for another
of the thing stated; left as it was, "a clean" was asked about as an unknown thing. The office
keeps no record of how clean or straight a thing is, so the describing words choose nothing."""

from __future__ import annotations

import re
from collections.abc import Container

from assistantx.core import language

# "a clean one", "a nice clean one", "a working one", "a fresh pair": up to two describing
# words; "a new pair of boots" names its thing, never one said before
_DESCRIBED_ONE = re.compile(
    r"\b(?P<article>an?)\s+(?P<words>[^\W\d_]+(?:\s+[^\W\d_]+)?)\s+(?:one|pair(?!\s+of\b))\b",
    re.IGNORECASE,
)


def described_ones(text: str, items: Container[str]) -> str:
    """``text`` with each "a <describing words> one" read as "another one"; words that name a
    thing of ``items`` ("a paper one" where paper is an item) are left as they are."""

    def read(match: re.Match[str]) -> str:
        words = match.group("words").lower().split()
        if not all(_describes(w, items) for w in words):
            return match.group(0)
        return "another one"

    return _DESCRIBED_ONE.sub(read, text)


def _describes(word: str, items: Container[str]) -> bool:
    """An adjective ("clean") or a present participle ("working"), no thing of the office."""
    if word in items:
        return False
    return "ADJ" in language.lemmas(word) or (
        word.endswith("ing") and language.is_present_participle(word)
    )
