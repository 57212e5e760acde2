"""Checks of the model's outputs against memory, before anything runs.

- Perception's focus (people, places, groups, items) must resolve; it is returned with ids,
  and the requester is added to a non-empty focus, because later agents see only the people
  in focus (an empty focus shows everyone);
- every action of a Decision must ground (``Resolver.ground``); a ``stop`` must be the last
  action; a QR code that the person already holds unused may not be sent again;
- Reflection's memory updates must name known people, item types, items and holders, by
  the resolver's one rule (``Resolver.ground_update``), which the loop applies too.

Each check raises :class:`~assistantx.core.errors.ModelOutputError` with a message written
for the model, which the structured call feeds back; a name that does not resolve is the
model's mistake, so the resolver's ``GroundingError`` is turned into one here, by name. Any
other exception is a bug of ours and propagates.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core.actions import Action, SendQR, Stop
from assistantx.core.errors import GroundingError, ModelOutputError, UnknownNameError
from assistantx.core.trace import Percept
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import MemoryUpdate


def focus_ids(percept: Percept, resolver: Resolver, requester: str) -> Percept:
    """The percept with every name replaced by its id (and the requester added to a non-empty
    list of people); ModelOutputError when a name does not resolve."""
    try:
        people: list[str] = [resolver.person(p) for p in percept.people]
        places = [_place_or_facility(resolver, p) for p in percept.places]
        groups = [resolver.group(g) for g in percept.groups]
        items = [_item_or_type(resolver, i) for i in percept.items]
    except GroundingError as exc:
        raise ModelOutputError(str(exc)) from exc
    if people and requester not in people:  # no people at all: no filter, everyone is shown
        people.insert(0, requester)
    return percept.model_copy(
        update={
            "people": list(dict.fromkeys(people)),
            "places": list(dict.fromkeys(places)),
            "groups": list(dict.fromkeys(groups)),
            "items": list(dict.fromkeys(items)),
        }
    )


def _place_or_facility(resolver: Resolver, name: str) -> str:
    """A facility id when the name is a facility (the renderer filters facilities by id)."""
    try:
        return resolver.facility(name)
    except GroundingError:
        return resolver.place(name)


def _item_or_type(resolver: Resolver, name: str) -> str:
    try:
        return resolver.item(name)
    except UnknownNameError:
        if ":" in name:
            raise
        return resolver.item_type(name)


def check_actions(actions: Sequence[Action], resolver: Resolver, stm: ShortTermMemory) -> None:
    """ModelOutputError with a message for the model when an action cannot run as proposed."""
    for index, action in enumerate(actions):
        where = f"actions[{index}] ({action.type})"
        try:
            grounded = resolver.ground(action)
        except GroundingError as exc:
            raise ModelOutputError(f"{where}: {exc}") from exc
        if isinstance(grounded, Stop) and index != len(actions) - 1:
            raise ModelOutputError(
                f"{where}: stop ends the instruction, so it must be the last action"
            )
        if isinstance(grounded, SendQR) and stm.embodied.unused_code(
            grounded.contact, grounded.item, grounded.purpose
        ):
            raise ModelOutputError(
                f"{where}: {grounded.contact} already holds an unused QR code to "
                f"{grounded.purpose} {grounded.item}; never resend the same QR code"
            )


def ground_updates(updates: Sequence[MemoryUpdate], resolver: Resolver) -> list[MemoryUpdate]:
    """Every update with ids; ModelOutputError naming the first one that does not ground."""
    grounded = []
    for index, update in enumerate(updates):
        try:
            grounded.append(resolver.ground_update(update))
        except GroundingError as exc:
            raise ModelOutputError(f"updates[{index}] ({update.kind}): {exc}") from exc
    return grounded
