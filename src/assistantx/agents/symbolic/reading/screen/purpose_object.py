"""How many words after a purpose's verb belong to the purpose the office declares: "something
to check *continuity* with" where a multimeter's purposes include "check continuity", "to
take *notes* with", "to write *on*". A purpose names its tool by the verb and its object
together, so the object is part of the phrase: never left behind to be glued to the tool's
name ("a multimeter continuity"). The longest declared phrase wins ("check continuity" over
"check"); none: no word (the verb alone is the purpose)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import language

# "check the continuity of the loom" is said, never declared: a purpose is short
_LONGEST_OBJECT = 3


def purpose_words(declared: Callable[[str], list[str]], verb: str, tail: Sequence[str]) -> int:
    """The number of words of ``tail`` (the words after the purpose's verb) that, with
    ``verb``, make the longest purpose ``declared`` knows an item for; 0 when none does."""
    for n in range(min(_LONGEST_OBJECT, len(tail)), 0, -1):
        if declared(" ".join([verb, *(w.lower() for w in tail[:n])])):
            return n
    return 0


# "check the tread depth" said, "check tread depth" listed: an article before the object
# changes nothing about the purpose, so both sides are compared without it
_ARTICLES = frozenset({"a", "an", "the"})


def without_articles(phrase: str) -> str:
    """A purpose's words without "a", "an", "the" ("check the tread" → check tread)."""
    return " ".join(w for w in phrase.lower().split() if w not in _ARTICLES)


def object_nouns(tail: Sequence[str], said: int) -> int:
    """The words of ``tail`` the purpose's object takes up when nouns go on after the declared
    words ("check the tread *wear*" where "check the tread" is declared): a compound the
    object heads is still what the tool works on, never a word glued to the tool's name ("a
    tread depth gauge wear"). Only after an object was said (``said`` > 0); a word the
    dictionary also reads as an adverb, preposition, auxiliary or determiner ends it ("for",
    "today")."""
    n = said
    while 0 < said and n < len(tail) and n - said < _LONGEST_OBJECT and _noun_only(tail[n]):
        n += 1
    return n


def _noun_only(word: str) -> bool:
    found = language.lemmas(word.lower())
    return "NOUN" in found and not found.keys() & {"ADV", "ADP", "AUX", "DET", "PRON"}
