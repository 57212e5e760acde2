"""The screen's English: the word lists of ``english.yaml`` it reads pieces with, phrases as
tuples of words, and the small word-matching helpers every rule shares."""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

from assistantx.core import language
from assistantx.core.english import entries_of
from assistantx.core.english import words as english_words

# Words that start a noun phrase: after a service verb they make it a request ("scan *my* ...").
DETERMINERS = english_words("screen_determiners")


@dataclass(frozen=True)
class English:
    """The word lists of ``english.yaml``, phrases as tuples of words."""

    lead_in: frozenset[str]
    withdraw: tuple[tuple[str, ...], ...]
    negators: tuple[tuple[str, ...], ...]
    negation_fillers: frozenset[str]
    destructive: tuple[tuple[str, ...], ...]
    # "rip up", "snap": destroying only said of a colleague's thing ("snap a photo" is none)
    destructive_of_others: tuple[tuple[str, ...], ...]
    unsafe_acts: tuple[tuple[str, ...], ...]  # fire, false alarms: a danger, never done
    waste_containers: tuple[
        tuple[str, ...], ...
    ]  # "the skip": putting a thing there disposes of it
    copulas: tuple[tuple[str, ...], ...]
    away: tuple[tuple[str, ...], ...]
    here: tuple[tuple[str, ...], ...]
    location_prepositions: frozenset[str]
    conditions: tuple[tuple[str, ...], ...]
    fact_openers: frozenset[str]
    another_one: tuple[str, ...]
    others_ones: tuple[str, ...]  # "someone else's": a colleague's one of the thing said
    purpose_heads: tuple[str, ...]
    purpose_links: tuple[str, ...]
    purpose_tail: frozenset[str]
    service_verbs: frozenset[str]
    serial_verbs: frozenset[str]  # "go print it": a verb that leads another, no modifier
    service_products: frozenset[str]
    modifier_prepositions: frozenset[str]
    courtesy: frozenset[str]
    own_item_lost: tuple[tuple[str, ...], ...]
    exclusion_openers: frozenset[str]
    elliptical_withdrawals: tuple[tuple[str, ...], ...]


@functools.cache
def english() -> English:
    raw = entries_of()

    def phrases(key: str) -> tuple[tuple[str, ...], ...]:
        # longest first, so "throw away" wins over "throw"
        found = {tuple(language.words(str(p))) for p in raw[key]}
        return tuple(sorted(found, key=lambda p: (-len(p), p)))

    def word_set(key: str) -> frozenset[str]:
        return frozenset(w for p in raw[key] for w in language.words(str(p)))

    return English(
        lead_in=word_set("lead_in"),
        withdraw=phrases("withdraw"),
        # "I *hardly* need a stapler": an adverb that denies the verb after it negates the
        # errand as "don't" does
        negators=tuple(
            sorted(
                set(phrases("negators")) | {(w,) for w in word_set("negative_adverbs")},
                key=lambda p: (-len(p), p),
            )
        ),
        negation_fillers=word_set("negation_fillers"),
        destructive=phrases("destructive"),
        destructive_of_others=phrases("destructive_of_others"),
        unsafe_acts=phrases("unsafe_acts"),
        waste_containers=phrases("waste_containers"),
        copulas=phrases("copulas"),
        away=phrases("away"),
        here=phrases("here"),
        location_prepositions=word_set("location_prepositions"),
        conditions=phrases("conditions"),
        fact_openers=word_set("fact_openers"),
        another_one=tuple(sorted((str(p) for p in raw["another_one"]), key=lambda p: -len(p))),
        others_ones=tuple(sorted((str(p) for p in raw["others_ones"]), key=lambda p: -len(p))),
        purpose_heads=tuple(str(p) for p in raw["purpose_heads"]),
        purpose_links=tuple(str(p) for p in raw["purpose_links"]),
        purpose_tail=word_set("purpose_tail"),
        service_verbs=word_set("service_verbs"),
        serial_verbs=word_set("serial_verbs"),
        service_products=word_set("service_products"),
        modifier_prepositions=word_set("modifier_prepositions"),
        courtesy=word_set("courtesy"),
        own_item_lost=phrases("own_item_lost"),
        exclusion_openers=word_set("exclusion_openers"),
        elliptical_withdrawals=phrases("elliptical_withdrawals"),
    )


def split_words(text: str) -> list[str]:
    return language.words(text)


def starts_with(words: list[str], at: int, phrase: tuple[str, ...]) -> bool:
    # asked of every phrase at every word: the first word is compared before any slice
    if phrase and (at >= len(words) or words[at] != phrase[0]):
        return False
    return tuple(words[at : at + len(phrase)]) == phrase


Phrases = tuple[tuple[str, ...], ...]


def while_clause(words: list[str], subjects: Phrases, states: Phrases, openers: Phrases) -> bool:
    """Whether the words hold a clause of its own of one of ``openers``, a subject and a
    state ("while she's out", "when he isn't looking")."""
    for n in range(len(words)):
        for opener in openers:
            if not starts_with(words, n, opener):
                continue
            at = n + len(opener)
            for subject in subjects:
                if starts_with(words, at, subject) and any(
                    starts_with(words, at + len(subject), state) for state in states
                ):
                    return True
    return False


def phrases_pattern(key: str) -> str:
    """A regular expression (no groups) matching any phrase of ``english.yaml``'s list
    ``key`` as typed, longest first, with any run of spaces between its words."""
    return "|".join(
        r"\s+".join(re.escape(w) for w in entry.split())
        for entry in sorted(entries_of()[key], key=len, reverse=True)
    )
