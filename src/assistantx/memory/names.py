"""Tolerant name matching: case, spacing, punctuation, titles and possessives.

People say "Dr. Zhang", "zhang's", "ZHANG  Wei"; all mean the person ``zhang``. Matching is
tiered so that exact names win over partial ones, and an answer is only given when exactly one
thing matches in the best tier; otherwise the caller reports ambiguity, never guesses.
"""

from __future__ import annotations

import difflib
import functools
import re
from collections.abc import Iterable

from assistantx.core import english
from assistantx.core.language import fold

TITLES = english.words("titles")
_NON_WORD = re.compile(r"[\W_]+")


# A reader normalizes the office's names and the message's words many times over (650 k calls
# in the agents' tests): the last answers are kept.
@functools.lru_cache(maxsize=8192)
def normalize(text: str) -> str:
    """Fold (case, diacritics: "José Müller" is "jose muller"), drop punctuation, possessive
    's, and titles; collapse spaces."""
    text = fold(text)
    text = re.sub(r"'s\b", "", text)
    split = [w for w in _NON_WORD.split(text) if w]
    # "Robin A": a one-letter last word after a name is an initial, not the article "a"
    initial = split[-1:] if len(split) > 1 and len(split[-1]) == 1 else []
    words = [w for w in split[: len(split) - len(initial)] if w not in TITLES]
    return " ".join(words + initial) if words else ""


class NameIndex:
    """Maps names to ids in tiers: 0 = ids, full names and declared aliases; 1 = name words."""

    def __init__(self) -> None:
        self._ids: set[str] = set()
        self._tiers: list[dict[str, set[str]]] = [{}, {}]

    def add(self, entity_id: str, names: Iterable[str], words: Iterable[str] = ()) -> None:
        self._ids.add(entity_id)
        for name in (entity_id, entity_id.replace("_", " "), *names):
            key = normalize(name)
            if key:
                self._tiers[0].setdefault(key, set()).add(entity_id)
        for word in words:
            key = normalize(word)
            if key:
                self._tiers[1].setdefault(key, set()).add(entity_id)

    def lookup(self, name: str, *, fuzzy: float = 0.86) -> list[str]:
        """Ids that match ``name`` in the best tier (several = ambiguous; none = unknown).

        An exact id is that id before any name matching: ``robin_a`` normalizes to "robin" (the
        'a' reads as an article), which a colleague also called Robin would match as well."""
        if name.strip() in self._ids:
            return [name.strip()]
        key = normalize(name)
        if not key:
            return []
        for tier in self._tiers:
            if key in tier:
                return sorted(tier[key])
        if fuzzy < 1.0:
            for tier in self._tiers:
                close = difflib.get_close_matches(key, list(tier), n=3, cutoff=fuzzy)
                found = sorted({i for k in close for i in tier[k]})
                if found:
                    return found
        return []

    def keys(self) -> list[str]:
        return sorted({k for tier in self._tiers for k in tier})
