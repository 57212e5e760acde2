"""A thing said to live somewhere: "the moisture meter that *lives in* the drying cabinet",
"the tape that's *kept in* the cupboard". A residence verb before a preposition of where says
where the thing is kept, so the facility after it is where to fetch it from, never a request
for that facility's service (the cabinet dries, yet nobody asked to dry the meter)."""

from __future__ import annotations

from collections.abc import Mapping

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import english

_RESIDENCE = english.words("residence_verbs")
_WHERE = frozenset({"in", "at", "on", "inside", "by", "near", "beside", "under"})
# Words of direction a speaker puts between the verb and the preposition ("lives *over* in
# the lab", "sits *up* on the shelf"): they change nothing of where it is.
_DIRECTION = frozenset({"over", "up", "down", "out", "back", "round", "around", "across"})
# Before the verb, the words that make it a wish, not a statement: "my seeds need *to* sit in
# the drying cabinet", "they *should* stay in it" ask for the cabinet's service after all.
_WISHED = english.words("modal_auxiliaries") | {"to", "let"}


def lives_there(facility: Mention, before: Mapping[int, Mention]) -> bool:
    """Whether ``facility`` is said as where a thing lives: a residence verb, then (words of
    direction allowed) a preposition of where, then the facility, the verb stating where it
    is, not wished ("need to sit in"). ``before``: each mention's
    start mapped to the mention just before it in the clause (articles are no mentions)."""
    w = before.get(facility.start)
    if w is None or w.kind != "word" or not w.ids or w.ids[0] not in _WHERE:
        return False
    v = before.get(w.start)
    while v is not None and v.kind == "word" and v.ids and v.ids[0] in _DIRECTION:
        v = before.get(v.start)
    if v is None or v.kind != "word" or not v.ids or v.ids[0] not in _RESIDENCE:
        return False
    wish = before.get(v.start)
    return not (wish is not None and wish.kind == "word" and wish.ids and wish.ids[0] in _WISHED)
