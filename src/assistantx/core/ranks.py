"""The ranks an office writes before surnames ("Station Officer Delaney", "Watch Manager
Quinn"), each with the one person who holds it: a colleague says "the station officer" of
them. The reader reads such a phrase as that person, and the consent guard counts it as
naming them, from this one table, so the two never disagree on who "the Station Officer" is.

A rank two people hold names neither (it is no name of either); a courtesy title ("Dr",
"Mr") is no rank; words of two letters ("SO Delaney") are initials, not words people say.
One word before a surname is as often a given name or a nickname ("Big Dave Okoro") as a
rank, so it is a rank only where the dictionary knows it as a noun and never as an
adjective ("Director Watanabe", "Captain MacLeod": "the Director"; not "Big", "Young" or
"Dave"), and no one in the office bears it as a name."""

from __future__ import annotations

import re

from assistantx.core import language
from assistantx.core.office import Office

# Titles of address, not roles: "Dr. Zhang" does not make "the doctor" Zhang.
COURTESY_TITLES = frozenset(
    {"a", "an", "the", "our", "mr", "mrs", "ms", "mx", "miss", "sir", "madam", "dr"}
)
_ARTICLES = frozenset({"the", "our"})


def rank_titles(office: Office) -> dict[str, frozenset[str]]:
    """Each rank phrase (folded words, "station officer") with the one person holding it."""
    return {rank: ids for rank, ids in _ranks(office).items() if len(ids) == 1}


def shared_ranks(office: Office) -> dict[str, frozenset[str]]:
    """Each rank phrase that several colleagues hold ("driver" of "Driver Lund" and "Driver
    Park"), with them: "the driver" names one of them, and which is asked; it is no name of
    any of them (the consent guard reads only ``rank_titles``)."""
    return {rank: ids for rank, ids in _ranks(office).items() if len(ids) > 1}


def _ranks(office: Office) -> dict[str, frozenset[str]]:
    held: dict[str, set[str]] = {}
    for p in office.people:
        surname = said_words(p.name)[-1:]
        for alias in p.aliases:
            said = said_words(alias)  # as written: "Watch Manager Quinn" keeps "manager"
            if len(said) < 2 or said[-1:] != surname:
                continue
            rank = said[:-1]
            while rank and rank[0] in _ARTICLES:
                rank = rank[1:]
            if not rank or not all(len(w) > 2 and w not in COURTESY_TITLES for w in rank):
                continue
            if len(rank) > 1 or _rank_noun(rank[0]):
                held.setdefault(" ".join(rank), set()).add(p.id)
    names = {w for p in office.people for w in said_words(p.name)}
    return {
        rank: frozenset(ids)
        for rank, ids in held.items()
        if not set(rank.split()) <= names  # "Olive B" is no rank
    }


def _rank_noun(word: str) -> bool:
    """A word that can stand alone as a rank: a noun, never an adjective ("director", not
    "big"; "chief" is both, and a declared nickname of its own where an office means it)."""
    kinds = language.lemmas(word)
    return "NOUN" in kinds and "ADJ" not in kinds


def said_words(name: str) -> list[str]:
    """The words of a name as written, folded, with no word dropped ("watch manager quinn")."""
    return re.sub(r"[^\w\s]", "", language.fold(name).replace(".", " ")).split()
