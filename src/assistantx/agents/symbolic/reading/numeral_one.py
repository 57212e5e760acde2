"""A texted "1" standing for "one", the pro-form of a thing just named ("coffee for me and 1
for Wang"): read as "one" ("... and one for Wang"), so the second coffee is a task of its own
as with the word spelled out. Left as said, "1 for Wang" was no pro-form and only Wang's
coffee was made.

Only a lone "1" after a joining word ("and", "&", "plus", "n") and before "for" or "more" is
the pro-form; "desk 1", "1 sugar", "1 for 1" and "at 1" keep their digit."""

from __future__ import annotations

import re

_ONE = re.compile(r"(?P<join>(?:\b(?:and|plus|n)|&)\s+)1(?=\s+(?:for|more)\b)", re.IGNORECASE)
_LEFT = re.compile(r"\b1\s+for\s+1\b")


def numeral_ones(text: str) -> str:
    """``text`` with each texted pro-form "1" spelled "one"."""
    if _LEFT.search(text):
        return text  # "1 for 1": a count, no pro-form
    return _ONE.sub(lambda m: f"{m.group('join')}one", text)
