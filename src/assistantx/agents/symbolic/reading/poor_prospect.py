"""Poor prospects told: "no chance of getting the quarterly binders printed before 4", "not a
hope of finishing the slides today", "little point in copying them". A denied or slim
prospect ("no", "little", "not a" + "chance"/"hope"/"way"/"point" ...) of a doing (its
gerund after "of"/"in") is venting: it asks nobody for anything, whatever work the gerund
names. Read as what was left, the causative "getting X printed" was taken as asked, and the
speaker's file was printed.

"any chance of getting it printed?" and "no rush on getting it printed" ask, and are none of
this: only a listed opener denies the prospect, and only a prospect's noun follows it. A
colleague's name may stand before it ("Hope, no chance of ..."), as may the prospect's noun
be one ("no hope of ..." where Hope works here): the words are read as said, not as names.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import english, language

_OPENERS = tuple(
    sorted(
        (tuple(p.split()) for p in english.entries("poor_prospect_openers")),
        key=lambda p: -len(p),
    )
)
# "hope" is a colleague's name in some offices: kept here, never with the English data, as
# ``screen.hope`` keeps it
_NOUNS = english.words("poor_prospect_nouns") | {"hope", "hopes"}
_DOERS = english.words("poor_prospect_doers")
# what joins the prospect to its doing: "chance *of* getting", "point *in* copying"
_JOINS = frozenset({"of", "in"})
# the words a prospect's noun may carry before its join: "no *real* chance of", "no hope *in
# hell* of"
_NOUN_REACH = 2
_JOIN_REACH = 2


def poor_prospect(w: Sequence[str], named: Callable[[str], bool]) -> bool:
    """Whether the content words ``w`` of a piece open with a poor prospect of a doing ("no
    chance of getting X printed"); ``named``: whether a word is a colleague's name here,
    which may stand first as whom it is said to."""
    if len(w) > 1 and named(w[0]) and _opener_at(w, 1):
        w = w[1:]  # "Hope, no chance of ...": said to a colleague
    n = _opener_at(w, 0)
    if n is None:
        return False
    noun = next((k for k in range(n, min(n + _NOUN_REACH, len(w))) if w[k] in _NOUNS), None)
    if noun is None:
        return False
    joined = next(
        (k for k in range(noun + 1, min(noun + 1 + _JOIN_REACH + 1, len(w))) if w[k] in _JOINS),
        None,
    )
    if joined is None:
        return False
    k = joined + 1
    while k < len(w) and w[k] in _DOERS:
        k += 1
    return k < len(w) and language.is_present_participle(w[k])


def _opener_at(w: Sequence[str], at: int) -> int | None:
    """Where the words after the opener said at ``at`` begin; None without one."""
    for opener in _OPENERS:
        if tuple(w[at : at + len(opener)]) == opener:
            return at + len(opener)
    return None
