"""Each thing's own "for X" in a list of two: "a latte for me and a copy of my contract for
Fang". When a clause is read as two parts, each with its own things (a product named with
what it is made of, beside another thing: ``TaskReader._made_of_apart``), and each part names
someone right after its own things ("for me", "to Wang"), that person receives that part's
things: X receives A and Y receives B. Reading both parts with the clause's last recipient
gave the latte to Fang, a wrong physical action.

Where only one part names whom it is for ("a coffee and a copy of my contract for Fang"), the
clause's roles stand as before, read whole. A clause with one thing read and a noun the office
does not know after it ("a tea for Will and a stapler for me", no stapler here) keeps the
thing's own "for Will": the later "for me" is the unknown thing's."""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.core import language

# The small words a clause's word mentions hold besides nouns ("for", "of", "and").
_JOINING = frozenset({"for", "of", "and", "to", "from", "with", "please", "pls", "too", "also"})
# The words that stand for the thing already named ("and *one* for Wang").
_ONE_AGAIN = frozenset({"one", "ones", "another", "same", "more", "two", "three", "each", "other"})


def roles_of_parts(roles: Roles, parts: Sequence[Clause]) -> list[Roles]:
    """The roles each part (in the order said) is read with: its own recipients, said after
    its first thing and before the next part's first thing, where every part has some; else
    the clause's roles for each, as before."""
    starts = [min((m.start for m in p.objects()), default=-1) for p in parts]
    if any(s < 0 for s in starts) or starts != sorted(starts):
        return [roles for _ in parts]
    bounds = [*starts[1:], 1 << 30]
    own = [
        [(w, at) for w, at in zip(roles.recipient, roles.recipient_at, strict=True) if s <= at < e]
        for s, e in zip(starts, bounds, strict=True)
    ]
    if not all(own):
        return [roles for _ in parts]
    return [
        dataclasses.replace(
            roles, recipient=[w for w, _ in mine], recipient_at=[at for _, at in mine]
        )
        for mine in own
    ]


def own_for_of_one(roles: Roles, clause: Clause) -> Roles:
    """ "a tea for Will and a stapler for me", where the office has no stapler: the one thing
    read keeps the "for" right after it (Will); the later "for me" is the unread thing's,
    after its noun. The clause's roles as before where it reads several things, or names
    nobody after its one thing, or no other noun comes between its recipients."""
    objects = clause.objects()
    if len(objects) != 1 or roles.each:
        return roles
    thing = objects[0]
    said = list(zip(roles.recipient, roles.recipient_at, strict=True))
    after = [(w, at) for w, at in said if at >= thing.end]
    if len(after) < 2 or len(after) != len(said):
        return roles
    # a noun the reader could not place between the thing's own recipient and a later one
    nouns = [
        m.start
        for m in clause.mentions
        if m.kind == "word" and after[0][1] < m.start < after[-1][1] and _a_noun(m.text)
    ]
    if not nouns:
        return roles
    own = [(w, at) for w, at in after if at < nouns[0]]
    return dataclasses.replace(
        roles, recipient=[w for w, _ in own], recipient_at=[at for _, at in own]
    )


def _a_noun(text: str) -> bool:
    """A noun, or a word the dictionary lacks ("widget" is a thing's name all the same); not
    "one", "another" or a numeral, which stand for the thing read ("a coffee for me and one
    for Wang": another coffee, read by ``numeral_one``)."""
    word = text.lower()
    if word in _JOINING or word in _ONE_AGAIN or word.isdigit():
        return False
    return language.is_noun(word) or not language.lemmas(word)
