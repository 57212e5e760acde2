"""The requester's own thing that the office knows of no such thing of theirs ("heat up my
lunch" from someone with no lunch in the fridge, "bring me my book" from someone who owns no
book): going for it would move for a request nobody can meet (it drove the robot and ended
"no one could hand over the lunch"). Said in words and asked where it is, before anything
moves.

A service's item counts only where the office keeps that type for its owners (lunches in a
fridge): there the office's record is where the robot would fetch it, so no record of theirs
means nothing to fetch. A type people carry about (a badge, a stapler) is not listed
exhaustively, and stays as read. A place said for it (``Task.source``) already says where. A
fetch of their own thing to themselves asks this in ``frames._check`` (``none_of_yours``)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# The question's words, beside the frames' other questions.
NONE_OF_YOURS = "As far as I know, you have no {name} of your own here. Where is it?"


def none_of_yours(office: Office, type_id: str) -> str:
    """The question for the requester's own ``type_id`` that the office knows none of."""
    return NONE_OF_YOURS.format(name=office.item_type(type_id).name)


def _kept_for_owners(office: Office, type_id: str) -> bool:
    """Whether the office keeps ``type_id`` for its owners somewhere (a fridge, a locker)."""
    return any(office.keeper(p, type_id) is not None for p in office.owners_of(type_id))


def own_item_unknown(
    office: Office, tasks: Sequence[Task], requester: str, kinds: Mapping[str, str | None]
) -> str | None:
    """The question for the first of ``tasks`` that is a service on the requester's own
    personal item (``kinds``: each item type's kind), of a type the office keeps for its
    owners, where it keeps none of theirs and no place was said; None when there is none."""
    for t in tasks:
        if t.kind == "transfer" or t.item is None or t.owner != requester:
            continue
        if t.source is not None or kinds.get(t.item) != "personal":
            continue
        if requester not in office.owners_of(t.item) and _kept_for_owners(office, t.item):
            return none_of_yours(office, t.item)
    return None
