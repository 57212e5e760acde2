"""The words of a message and where its clauses end, read on the raw text by the surface steps
that put back a comma a person left out ("my phone's on 2%, pls ...", "get my swab tested,
the reading ...")."""

from __future__ import annotations

import re

# a word as typed, with its apostrophes and a percent sign ("phone's", "2%")
WORD = re.compile(r"[\w'’%]+")
# where a clause ends: a stop, a comma, a colon or a dash
CLAUSE_END = re.compile(r"[.!?;,:\n]|\s[-–—]\s")


def clause_ends_between(text: str, before: re.Match[str], after: re.Match[str]) -> bool:
    """Whether a clause ends in ``text`` between the words ``before`` and ``after``."""
    return bool(CLAUSE_END.search(text[before.end() : after.start()]))


def with_commas_at(text: str, cuts: list[int]) -> str:
    """``text`` with a comma put at each offset of ``cuts`` (in the order said)."""
    for at in sorted(cuts, reverse=True):
        text = f"{text[:at]},{text[at:]}"
    return text
