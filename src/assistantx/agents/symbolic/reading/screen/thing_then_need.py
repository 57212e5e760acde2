"""A thing said to be somewhere, then the speaker's own need of it joined by "and": "the label
maker is still locked in the stationery cupboard and I need it at my desk", "my lunch is
stuck in the fridge and I want it up here". The need is a request of its own (its "it" is the
thing the statement named), cut from the statement, which stays context, as a need after an
account of the speaker's own doing is. Only the speaker's need is cut ("and I need", "and we
want"): "... and needs heating", "... if anyone needs it" and "..., fyi" stay as they were."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.english import phrases_pattern

# "the label maker is still locked in", "my lunch's in", "Ken's ruler was left at": a thing's
# noun phrase (a determiner or a possessive, then up to three words) as the subject of a
# copula, and where it is (a preposition of place within a few words): a statement of where
# the thing is kept, not of what is wrong with it ("the printer is jammed and I need ...")
_THING_SAID = re.compile(
    r"(?:(?:the|my|our|this|that|these|those|his|her|their)|[^\W\d_][\w-]*['’]s)"
    r"(?:\s+[^\W\d_][\w-]*){1,3}?(?:['’]s|\s+(?:is|are|was|were))"
    r"(?:\s+[^\W\d_][\w-]*){0,3}?\s+(?:in|inside|at|on|under|behind|by|with)\b",
    re.IGNORECASE,
)
# "and I need", "and we'd like": the speaker's own need, said with its subject
_OWN_NEED_JOINED = re.compile(
    rf"(?<=\w)\s+(?=and\s+(?:i|we)\s+(?:(?:really|still|just|do)\s+)?"
    rf"(?:{phrases_pattern('joined_needs')})\s+"
    rf"(?!(?:{phrases_pattern('nothing_needed')})\b))",
    re.IGNORECASE,
)


def need_after_thing(chunk: str) -> list[int]:
    """Where to cut ``chunk`` before the speaker's need joined to a statement of a thing
    that opens it; none where it opens otherwise."""
    if not _THING_SAID.match(chunk.lstrip()):
        return []
    return [m.end() for m in _OWN_NEED_JOINED.finditer(chunk)]
