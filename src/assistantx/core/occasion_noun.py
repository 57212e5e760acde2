"""Whether the word after a colleague's possessive names an occasion of theirs ("for Grace's
*meeting*", "for Mark's *workshop*"): the thing brought for it is for them. Read alike by the
reader (``agents/symbolic/reading/occasion``) and the consent guard (``runtime/recipients``),
so the colleague the reader gives the thing to is one the guard lets it go to.

An ordinary noun that is no function word, no place word ("Grace's desk": where she is met)
and no word of a benefit ("for Mark's sake") or a time ("Mark's day off"). The office's own
names of things are read before this by both (those are "Grace's stapler": hers)."""

from __future__ import annotations

from assistantx.core import english, language
from assistantx.core.receiving_place import PLACE_WORDS

_COMMON = english.words("common")
_NOT_OCCASIONS = frozenset({"sake", "benefit", "behalf"}) | english.words("time_possessors")


def occasion_noun(word: str) -> bool:
    """Whether ``word`` (folded) may name a colleague's occasion after their possessive."""
    if word in _COMMON or word in PLACE_WORDS or word in _NOT_OCCASIONS:
        return False
    return language.is_noun(word)
