"""A recipient given as a person's occasion: "bring some tape down to the post desk for
Grace's meeting", "take a ruler to the lounge for Mark's workshop". What is taken to a room
for a colleague's meeting, talk or workshop is for that colleague, so they receive it (unless
the clause names someone else to receive it); the room named is where the occasion is, not a
room the thing is handed to, so whom there to give it to is not asked. Without a room the
thing is taken to, the occasion says only why ("I need a ruler for Grace's workshop", "print
my file for Grace's meeting": the speaker's), and nothing changes.

The occasion is the noun right after the colleague's possessive ("Grace's *meeting*"), a word
that names no thing, place or work of the office (those keep their readings: "Grace's
stapler" is hers, "Grace's desk" where she is met) and no place word; a possessive of someone
not of the office ("for the client's meeting") is no person, and stays as it was.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.occasion_noun import occasion_noun


def is_occasion(tokens: Sequence[Token], following: Mention | None, end: int) -> bool:
    """Whether the mention after a possessive ending at token ``end`` is an occasion's noun:
    an ordinary word right after it (no thing, place or work of the office) that may name
    an occasion (``core.occasion_noun``)."""
    if following is None or following.kind != "word" or following.start != end:
        return False
    return occasion_noun(tokens[following.start].word)


def occasion_people(tokens: Sequence[Token], mentions: Sequence[Mention]) -> set[str]:
    """The colleagues a text names as the one a thing taken to a room is for, one person
    each after "for": whose occasion it is ("to the post desk for Grace's meeting") or the
    colleague themself ("take a ruler to the lounge for Mark", "drop my calculator at the
    kitchen for Rose"): a plain "for" a person beside a room says whom the thing is for,
    and the robot hands things to people, so that person receives it where they are met."""
    found: set[str] = set()
    for n, m in enumerate(mentions):
        if m.kind != "person" or len(m.ids) != 1 or m.start == 0:
            continue
        if tokens[m.start - 1].word != "for":
            continue
        following = mentions[n + 1] if n + 1 < len(mentions) else None
        if not m.possessive or is_occasion(tokens, following, m.end):
            found.add(m.ids[0])  # "for Mark", "for Mark's workshop"; not "for Mark's sake"
    return found if taken_to_a_room(tokens, mentions) else set()


_ARTICLES = frozenset({"the", "a", "an", "our", "their", "this", "that"})
_TO_A_ROOM = frozenset({"to", "into", "at"})


def taken_to_a_room(tokens: Sequence[Token], mentions: Sequence[Mention]) -> bool:
    """Whether the words take a thing to a room of the office: a place or facility after
    "to"/"into"/"at" (an article between): "to the post desk", "down to the lounge", "drop
    it at the kitchen"."""
    for m in mentions:
        if m.kind not in ("place", "facility"):
            continue
        k = m.start
        while k > 0 and tokens[k - 1].word in _ARTICLES:
            k -= 1
        if k > 0 and tokens[k - 1].word in _TO_A_ROOM:
            return True
    return False
