"""A place outside the office said by its proper name and the kind of place it is ("Westgate
branch", "the Northfield depot", "Eastgate campus"): capitalised words (after an article),
then the head noun of a place or an establishment. English puts a place's own name before
the common noun of its kind, so the capitalised words name that place, never a person of
the office ("Westgate" is no colleague to look up), and the phrase is a place's proper name
as much as "Broadcast House" is."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# The kinds of place, in the lexicon's words (data/english.yaml).
_HEADS = english.words("place_heads") | english.words("outside_workplaces")
_ARTICLES = frozenset({"the", "a", "an", "our", "their", "your"})


def place_head(word: str) -> bool:
    """Whether a lower-case word names a kind of place ("branch", "depots")."""
    nouns = language.lemmas(word).get("NOUN", ())
    return word in _HEADS or any(n in _HEADS for n in nouns)


def named_place(words: Sequence[Token]) -> bool:
    """Whether ``words`` are, whole, a named place: an optional article, one or more
    capitalised words, then one lower-case head noun of a place."""
    said = list(words)
    if said and said[0].word in _ARTICLES and said[0].text[:1].islower():
        said = said[1:]
    if len(said) < 2 or not said[-1].text[:1].islower() or not place_head(said[-1].word):
        return False
    return all(t.text[:1].isupper() and not t.possessive for t in said[:-1])
