"""The requester's own thing, said fetched for them and then worked on ("get my form, then
photocopy it for me", "get my tech pack for me, then scan it"): the fetch is only the robot
collecting it from the requester for the work, which hands it back with whatever the work
makes; never a question where the thing is.

On its own, "get me my form" from someone the office's data say holds their form asks where
it is (the robot cannot bring a thing to the one who has it). Followed by work on that same
thing for the same person, the fetch is the first leg of the work's own errand (the robot
comes for the thing, takes it to the doer or the facility, and brings it back), as a fetch
from a facility already is before work on the item ("get my lunch out of the fridge and heat
it"). Only where the fetching clause names no one else: "get my form initialled by Wang, then
copy it" says a colleague's part the office has no word for, and is still asked about.
"""

from __future__ import annotations

from collections.abc import Collection

from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# the kinds that move a thing on, never work on it
_MOVING = frozenset({"transfer", "send_file"})


def collected_for_work(
    office: Office,
    earlier: Task,
    made: list[Task],
    others_named: Collection[str],
    requester: str,
) -> bool:
    """Whether ``earlier`` fetches the requester's own thing, held by them as far as the
    office knows, to the requester, only to have the one task of ``made`` work on it for
    them; ``others_named``: the people the fetching clause named besides the requester."""
    if len(made) != 1 or others_named:
        return False
    work = made[0]
    return (
        earlier.kind == "transfer"
        and earlier.item is not None
        and earlier.owner == earlier.recipient == requester
        and earlier.source in (None, requester)
        # on the requester, not kept at a facility ("my lunch in the fridge": fetched from
        # there first, as before)
        and _on_them(office, requester, earlier.item)
        and work.kind not in _MOVING
        and work.item in (earlier.item, None)  # None: "it", the thing fetched
        and work.owner in (requester, None)
        and work.recipient == requester
    )


def _on_them(office: Office, person: str, type_id: str) -> bool:
    """Whether the office knows ``person`` has a ``type_id`` of their own on them (not kept
    at a facility, not an unknown whereabouts)."""
    return any(o.type == type_id and o.known and o.at is None for o in office.person(person).owns)
