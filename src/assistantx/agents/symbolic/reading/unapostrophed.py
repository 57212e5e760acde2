"""A name with a possessive word in it ("tailor's tape", "carpenter's rule") as people type
it without the apostrophe ("tailors tape"): the word keeps its "s". The lexicon keeps this
spelling as another name of the same thing, so the words are read as the thing and not
left for the rest of the sentence (a purpose, "to check a blazer size") to be taken for it.
"""

from __future__ import annotations

import re

_POSSESSIVE_S = re.compile(r"(\w)['’]s\b")


def unapostrophed(name: str) -> str:
    """``name`` with each possessive "'s" written as a plain "s" ("tailor's tape" →
    "tailors tape"); the name itself where it has none."""
    return _POSSESSIVE_S.sub(r"\1s", name)
