"""A room a thing is carried to is where the thing goes, not a service asked of the room:
"take my stapler to the meeting room", "can you take it over to the boardroom?".

A facility the assistant runs nothing at (a meeting room, a lounge booked by people) is
refused when it is asked for ("book the meeting room": I can't help with it). Said after
"to"/"into" with a verb of carrying, on a thing the message names (an item, or "it"/"them"
for one a statement named), it is only where the thing goes: the robot hands things to
people, so the reader then finds who there receives it (someone the message says needs it
or is there, or asks), never refuses the delivery as an errand it cannot run.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# Where a thing goes: "to the meeting room", "into the boardroom".
_TO = frozenset({"to", "into"})
# What may stand between the verb's object and "to": "take it *over* to", "run it *down* to".
_ARTICLES = frozenset({"the", "a", "an", "our", "this", "that"})
# Verbs that carry a thing somewhere (in any inflection): the dative and handing verbs of
# the word lists, and the plain verbs of carrying.
_CARRYING = frozenset(
    form
    for verb in (
        english.words("dative_verbs")
        | english.words("handing_verbs")
        | {"carry", "run", "pop", "move", "put", "leave"}
    )
    for form in {verb, *language.verb_forms(verb)}
)
# A thing said by pronoun, the one a statement before named ("Zhang needs my stapler. take
# *it* to the meeting room").
_THING_PRONOUNS = frozenset({"it", "them", "this", "these", "those"})


def carried_to(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether facility mention ``n`` is where a thing is carried: after "to"/"into" (an
    article between), with a verb of carrying before it and a thing carried (an item
    mention or a thing's pronoun) between the verb and the "to"."""
    start = mentions[n].start
    while start > 0 and tokens[start - 1].word in _ARTICLES:
        start -= 1
    if start == 0 or tokens[start - 1].word not in _TO:
        return False
    to = start - 1
    verb = next(
        (k for k in range(to - 1, -1, -1) if tokens[k].word in _CARRYING),
        None,
    )
    if verb is None:
        return False
    thing = any(m.kind == "item" and verb < m.start < to for m in mentions) or any(
        tokens[k].word in _THING_PRONOUNS for k in range(verb + 1, to)
    )
    return thing
