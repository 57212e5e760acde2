"""A group said as "them" with nobody named before it, the one who receives said later: "the
visitors loved the tour!! can we get them some water? bring it to me at reception".

"them" there is a group that is no colleague (no person of the office was named for it to
mean), so it cannot be looked up; a later clause of the message hands the thing on to the
speaker ("bring it to me", "drop them with me"): the speaker takes it to pass on. The clause of
"them" is read without the pronoun (as "can we get some water"), and the later clause's
recipient is the task's, as in "can we get some water? bring it to me". Where no later clause
gives it to the speaker, "them" is asked about as before ("Who do you mean by 'them'?"); a
singular "him"/"her" is one person, asked about as before too.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.agents.symbolic.reading.tokens import Token

# The pronoun of a group ("get *them* some water")
_GROUP = frozenset({"them"})
# What hands a thing on to the speaker in the later clause ("bring it *to* me", "leave it
# *with* me")
_HANDED = frozenset({"to", "with"})
# What the later clause hands on: the thing just asked for
_BACK = frozenset({"it", "them", "those", "these", "that", "this"})


def without_group_pronoun(
    tokens: Sequence[Token], clauses: Sequence[Clause], at: int, said: str
) -> Clause | None:
    """Clause ``at`` without its group pronoun ``said`` where a later clause hands the thing
    on to the speaker; None where "them" is to be asked about."""
    if said.lower() not in _GROUP:
        return None
    if not any(_to_speaker(tokens, c) for c in clauses[at + 1 :]):
        return None
    clause = clauses[at]
    kept = [m for m in clause.mentions if not (m.kind == "pronoun" and m.text.lower() in _GROUP)]
    if len(kept) == len(clause.mentions):
        return None
    return dataclasses.replace(clause, mentions=kept)


def _to_speaker(tokens: Sequence[Token], clause: Clause) -> bool:
    """Whether ``clause`` asks a thing said back ("it") handed to the speaker ("bring it to
    me")."""
    if not clause.cues:
        return False
    starts = [m.start for m in clause.mentions]
    if not starts:
        return False
    words = [t.word for t in tokens[min(starts) : max(m.end for m in clause.mentions)]]
    said = [t.word for t in tokens]
    handed = any(
        m.kind == "self" and not m.possessive and m.start > 0 and said[m.start - 1] in _HANDED
        for m in clause.mentions
    )
    return handed and bool(set(words) & _BACK)
