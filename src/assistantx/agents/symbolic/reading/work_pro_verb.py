"""A general verb with "it" stands for the work already asked for: "need my sample tested,
can Zosia run it?", "need my badge laminated before the meeting, can Sue do it", "need a scan
of my form, can Mark sort that out?".

English says the work once (the need names the service or its product) and refers back to
it with a pro-verb phrase: "do it", "run it", "sort it", "handle that", "deal with it". Said
right after a colleague asked with a request's modal ("can Zosia ..."), it asks that colleague
to do the work named, exactly as "can Zosia test it?" would (``named_doer``: a keeper of a
facility that offers it does it; anyone else is said not to and asked about). The verb alone
is no such reference: "can Rose run to the shop" runs nowhere near a service.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_PRO_VERBS = english.words("work_pro_verbs")
_OBJECTS = english.words("work_pro_objects")
_WITH = frozenset({"with"})  # "deal with it"


def work_referred_to(tokens: Sequence[Token], at: int) -> bool:
    """Whether the words from token ``at`` are a pro-verb of work with its object: "run it",
    "do that", "deal with it"."""
    if at >= len(tokens) or tokens[at].word not in _PRO_VERBS:
        return False
    k = at + 1
    if k < len(tokens) and tokens[k].word in _WITH:
        k += 1
    return k < len(tokens) and tokens[k].word in _OBJECTS
