"""A colleague's thing the requester gives back: they were lent it, so they have it.

"return Wang's stapler", "give Wang his stapler back": the requester has the owner's thing
now, though the office's record (the simulated world's holder, set from the office file) still
says the owner holds it. When the robot asks the requester to put that thing in the locker, the
requester deposits it as the person they are would: the record was out of date. Only for the
requester's own instruction, only for the owner's thing that goes back to its owner (the goal
has the owner holding it, or the requester's words give it back and name the owner), and only
while the record has it with its owner (or has no record of it): a thing another errand moved
is where that errand left it. The eval's simulator and the service run this same office, so
both read the hand-over alike."""

from __future__ import annotations

import re

from assistantx.core.office import Office
from assistantx.sim.requester import Wish

# The verb that gives back by itself, and the verbs of handing with "back" after them.
_GIVES_BACK = re.compile(
    r"\breturn\b|\b(?:give|take|bring|hand|pass|carry|drop|send)\b(?:\W+\w+){0,6}?\W+back\b",
    re.IGNORECASE,
)


def gives_back(office: Office, wish: Wish, item: str) -> bool:
    """Whether ``wish`` is for ``item`` to go back to its owner from the requester."""
    type_id, _, owner = item.partition(":")
    if owner == wish.requester or not office.is_person(owner):
        return False
    if wish.words is None:  # from the task's goal: the owner is to hold their own thing
        return owner in wish.recipients and (type_id, owner) in wish.whose_items
    return owner in wish.people and _GIVES_BACK.search(wish.words) is not None


def lent_to_requester(office: Office, holder: dict[str, str], wish: Wish, item: str) -> bool:
    """Whether the requester has ``item`` though the record says its owner does: a thing they
    give back whose record still has it with its owner, or has none of it."""
    owner = item.partition(":")[2]
    return holder.get(item, owner) == owner and gives_back(office, wish, item)
