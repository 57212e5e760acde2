"""A team or place said after "from" by a short name: "borrow a dev kit from QA", "grab a
spare laptop from IT", "a form from Finance".

A capitalised word after "from" that names no colleague is where the thing comes from, not
someone to look up. Where the word is one word of the name (or a synonym) of exactly one
facility or place of the office ("QA" of "the QA lab store"), it names that facility or
place, as its whole name would ("from the QA lab store"). Where it names none of them but is
an acronym in capitals or the common name of a team ("from HR", "from Finance"), the source
is left open: any one of the thing will do, found as for a request that names no source,
never a question about a person nobody has. "IT" in capitals after "from" is such a name,
never the pronoun ("from it" is written in lower case).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from assistantx.agents.symbolic.reading.lexicon import COMMON, Mention, MentionKind, key_of
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office

_TEAMS = english.words("team_words")
# the longest acronym read as a team's ("QA", "HR", "R&D" is two words): a longer word in
# capitals is shouted, not abbreviated
_ACRONYM = 5


class TeamSources:
    """The single words that name one facility or place of an office after "from"."""

    def __init__(self, office: Office) -> None:
        named: dict[str, set[tuple[MentionKind, str]]] = {}
        for f in office.facilities:
            for name in (f.name, *f.synonyms):
                for word in key_of(name).split():
                    named.setdefault(word, set()).add(("facility", f.id))
        for loc in office.locations:
            if loc.kind == "workstation":
                continue  # "Desk 3": a colleague's seat, named with its number
            for word in key_of(loc.name).split():
                named.setdefault(word, set()).add(("place", loc.id))
        # the word names one thing of the office: one facility (its room may share the word)
        self._one: dict[str, tuple[MentionKind, str]] = {}
        for word, things in named.items():
            if word in COMMON:
                continue
            facilities = {t for t in things if t[0] == "facility"}
            if len(facilities) == 1:
                self._one[word] = next(iter(facilities))
            elif not facilities and len(things) == 1:
                self._one[word] = next(iter(things))

    def read(self, tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
        """``mentions`` with a short name after "from" read as the facility or place it is
        a word of."""
        out = list(mentions)
        for n, m in enumerate(out):
            if not _short_name_after_from(tokens, m):
                continue
            found = self._one.get(tokens[m.start].word)
            if found is not None:
                kind, thing = found
                out[n] = replace(m, kind=kind, ids=(thing,), possessive=False)
        return out


def _short_name_after_from(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether ``m`` is one capitalised word right after "from", read as nobody."""
    if m.kind not in ("word", "pronoun") or m.end - m.start != 1 or m.start < 1:
        return False
    if tokens[m.start - 1].word != "from" or not m.text[:1].isupper():
        return False
    return m.kind == "word" or m.text.isupper()  # "from IT", never "from it"


def unknown_team(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether ``m`` (naming nothing of the office) is a team said after "from": an acronym
    in capitals ("HR") or a team's common name ("Finance"), not a colleague's name."""
    if not _short_name_after_from(tokens, m):
        return False
    text = m.text.replace("’", "'").removesuffix("'s")
    acronym = text.isalpha() and text.isupper() and 2 <= len(text) <= _ACRONYM
    return acronym or tokens[m.start].word in _TEAMS
