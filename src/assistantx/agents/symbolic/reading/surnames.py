"""A title goes with a surname: "Ms Okafor", "Mr Yang", "Prof Sato".

Which word of a full name is the family name is the office's own data: where it writes a
title before a name in an alias ("Dr. Zhang" of Zhang Wei, "Professor Kowalski" of Art
Kowalski), the word after the title is the first or the last word of that person's full
name, and the office writes its names in that order (family name first, or last). A
person's own alias with a title or a rank before one word of their name ("Inspector Morgan"
of Priya Morgan) says their own order, whatever the office's: one "Ms Nguyễn" makes an office
of English names family-first, but not Priya Morgan. An office that declares no titled
alias is read the English way: the family name last.

A name word that is one person's family name and another's given name ("Yang": Yang Lei's
family name, Liu Yang's given name) means, after a title, the one whose family name it is;
bare, it is still asked about.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import language
from assistantx.core.office import Office
from assistantx.core.ranks import COURTESY_TITLES
from assistantx.memory.names import TITLES

# the titles of address before a family name (not the articles of the titles' list)
_ADDRESS = frozenset(TITLES) - {"a", "an", "the", "our"}


def family_first(office: Office) -> bool:
    """Whether the office writes family names first: more of its titled aliases name the
    first word of the full name than the last (none: the English order, family name last)."""
    first = last = 0
    for p in office.people:
        words = _words(p.name)
        if len(words) < 2:
            continue
        for alias in p.aliases:
            said = _words(alias)
            if len(said) != 2 or said[0] not in _ADDRESS:
                continue
            first += said[1] == words[0]
            last += said[1] == words[-1]
    return first > last


def family_names(office: Office, key: Callable[[str], str]) -> dict[str, set[str]]:
    """The family name of each person of several name words, by ``key`` (the lexicon's
    lookup key) → the people whose family name it is."""
    office_at = 0 if family_first(office) else -1
    found: dict[str, set[str]] = {}
    for p in office.people:
        words = p.name.split()
        if len(words) < 2:
            continue
        at = _own_order(p.name, p.aliases)
        if k := key(words[office_at if at is None else at]):
            found.setdefault(k, set()).add(p.id)
    return found


def _own_order(name: str, aliases: Sequence[str]) -> int | None:
    """Where a person's own alias of a title or rank and one word of their name puts their
    family name ("Inspector Morgan" of Priya Morgan: -1, "Manager Mao" of Mao Jun: 0); None
    when no alias of theirs says."""
    words = _words(name)
    if len(words) < 2:
        return None
    for alias in aliases:
        said = _words(alias)
        if len(said) != 2 or said[0] in words or said[0] in ("a", "an", "the", "our"):
            continue
        if said[1] == words[0]:
            return 0
        if said[1] == words[-1]:
            return -1
    return None


def after_title(prev: str) -> bool:
    """Whether the word ``prev`` is a title of address ("Mr", "Ms", "Dr", "Prof") or a
    courtesy title, not an article."""
    return prev in _ADDRESS or (prev in COURTESY_TITLES and prev not in ("a", "an", "the", "our"))


def _words(name: str) -> list[str]:
    return language.fold(name).replace(".", " ").split()


def given_names(office: Office, key: Callable[[str], str]) -> dict[str, set[str]]:
    """The given name of each person of several name words, by ``key`` → the people whose
    given name it is; empty for an office that writes family names first (there a bare name
    is not read as the given one, ``given_name_meant``). A person whose own titled alias puts
    their family name first ("Ms Nguyễn" of Nguyễn Thị Mai) has their last word as given."""
    if family_first(office):
        return {}
    found: dict[str, set[str]] = {}
    for p in office.people:
        words = p.name.split()
        if len(words) < 2:
            continue
        at = -1 if _own_order(p.name, p.aliases) == 0 else 0
        if k := key(words[at]):
            found.setdefault(k, set()).add(p.id)
    return found
