"""A name said as where the thing goes in a clause of time about a later event: "stamp this
invoice before *it goes to Acme*", "... once they go off to Harlow". Such a clause says when
the work must be done, by what happens to the thing afterwards, not whom the robot hands it
to; a name nobody in the office has there is context, not someone to ask about.

The clause opens with a conjunction of time and a pronoun as its subject ("before it", "once
they", "before I head out to Pryce's": the speaker's own trip), and the name comes after its
"to", with no pause or new sentence between.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token

_TIME_OPENERS = frozenset({"before", "after", "once", "when", "until", "till"})
# the thing's going, or the speaker's or another's own trip ("before I head out to Pryce's")
_SUBJECTS = frozenset({"it", "they", "this", "that", "these", "those", "i", "we", "he", "she"})
_REACH = 6  # the most words from the conjunction to the name's "to"


def in_later_event(tokens: Sequence[Token], start: int) -> bool:
    """Whether the name at token ``start`` follows the "to" of a clause of time about a
    later event ("before it goes to Acme")."""
    to = start - 1
    if to < 1 or tokens[to].word != "to" or tokens[start].opens or tokens[start].after_pause:
        return False
    for k in range(to - 1, max(-1, to - 1 - _REACH), -1):
        if tokens[k].word in _TIME_OPENERS:
            return k + 1 < to and tokens[k + 1].word in _SUBJECTS
        if tokens[k].opens or tokens[k].after_pause:
            return False
    return False


def in_time_clause(tokens: Sequence[Token], at: int) -> bool:
    """Whether token ``at`` (a place's preposition) stands in a clause of time about a later
    event ("... before *it comes into* the studio"): where the thing goes afterwards, never
    where the request takes it."""
    for k in range(at - 1, max(-1, at - 1 - _REACH), -1):
        if tokens[k].word in _TIME_OPENERS:
            return k + 1 < at and tokens[k + 1].word in _SUBJECTS
        if tokens[k].opens or tokens[k].after_pause:
            return False
    return False
