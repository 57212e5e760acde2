"""Who and where is relevant to a goal, from the milestones and the office's truth.

An action that reaches nobody and nothing in these sets is redundant (DESIGN §5). The sets
are generous on purpose: everyone who could fill a part of the goal in truth (every owner of
a stapler, every guard of the printer), the requester, the groups the requester is in, and
every place where the robot could meet one of them.
"""

from __future__ import annotations

from typing import Any

from assistantx.core import task_kinds
from assistantx.core.goals import parse_milestone
from assistantx.core.office import Office
from assistantx.core.task_schema import kind_shape


def _owner(item: str) -> str:
    return item.partition(":")[2]


def _type(item: str) -> str:
    return item.partition(":")[0]


def _guards(office: Office, operation: str) -> set[str]:
    return {g for f in office.offering(operation) for g in f.guards}


def _kind_guards(office: Office, milestone: str) -> set[str]:
    """Everyone who runs an operation of the shape the milestone's task kind uses (printing,
    copying, heating ...)."""
    spec = task_kinds.of_milestone(milestone)
    shape = kind_shape(spec.id) if spec is not None else None
    if shape is None:
        return set()
    return {g for op in office.with_shape(shape) for g in _guards(office, op.id)}


def relevant_people(office: Office, requester: str, goal: list[dict[str, Any]]) -> set[str]:
    people = {requester}
    people.update(g.id for g in office.groups if requester in g.members)
    for milestone in goal:
        name, args = parse_milestone(milestone)
        match name:
            case "holds":
                person, item = args
                people.add(person)
                people.update(_item_people(office, item))
            case _ if (spec := task_kinds.of_milestone(name)) and spec.by_person:  # sign, seal
                people.update((_owner(args[0]), *args[1:]))  # the named doer, if any
                tool = task_kinds.tool_type(spec.id, office)  # else whoever owns the tool
                people.update(office.owners_of(tool) if tool else ())
            case "printed" | "copied":
                people.add(_owner(args[0]))
                people.update(_kind_guards(office, name))
            case "heated":
                people.add(_owner(args[0]))
                people.update(_item_people(office, args[0]))
                people.update(_kind_guards(office, name))
            case "received":
                people.update((args[0], _owner(args[1])))
            case "made":
                people.update(_item_people(office, args[0]))
            case "informed":
                people.add(args[0])
    return {p for p in people if p}


def _item_people(office: Office, item: str) -> set[str]:
    """Who could hand this item over: its owner(s), or the guards that make or keep it."""
    item_type, owner = _type(item), _owner(item)
    found: set[str] = set()
    made = office.making(item_type)
    if made is not None:
        found.update(_guards(office, made.id))
        if made.shape(office) == "transform":  # the copy comes back with the original
            found.add(owner)
        return found
    if office.is_supply(item):  # owned by nobody: its keepers hand it out
        return set(office.facility(owner).guards)
    found.update(office.owners_of(item_type) if owner == "*" else [owner])
    for person in list(found):
        if person == "*" or not any(p.id == person for p in office.people):
            continue
        for o in office.person(person).owns:
            keeper = office.keeper(person, item_type) if o.type == item_type else None
            if keeper is not None:  # kept at a facility (a fridge, a cupboard)
                found.update(keeper.guards)
    return found


def relevant_places(office: Office, people: set[str]) -> set[str]:
    places: set[str] = set()
    for p in office.people:
        if p.id in people:
            places.add(p.location)
            places.update(f.location for f in office.facilities if p.id in f.guards)
    return places
