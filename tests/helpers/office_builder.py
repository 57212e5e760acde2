"""The small offices the tests run on, written as data: each office module (``helpers.archive``,
``helpers.hostel``...) lists its people, things, operations and facilities with the short
calls below, and ``office_file`` lays them out as an office file (the dict ``parse_office``
reads) the way every one of them did by hand: a workstation a person, in the people's order
and named after it ("Desk 3"), each person's handle ``@id``, one group of everyone, the robot's
home. Every call of ``office_file`` gives a fresh dict, so a test may change its copy."""

from __future__ import annotations

import copy
import functools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from assistantx.core.office import Office, parse_office

Row = dict[str, Any]
# What an owned or supplied thing is written as: its item type's id, or the office file's row
# (``kept`` for one kept at a facility, or {"type": ..., "count": 3}).
Thing = str | Mapping[str, Any]

# The question a send-out service asks before it sends (courier desks in several offices).
ASKS_NAME_AND_ADDRESS = "the name and address of the place"


def _things(things: Iterable[Thing]) -> list[Row]:
    return [{"type": t} if isinstance(t, str) else dict(t) for t in things]


def kept(item_type: str, *, at: str, facility: str) -> Row:
    """A belonging kept at a facility (in a room) rather than on its owner's desk."""
    return {"type": item_type, "at": at, "facility": facility}


def room(place_id: str, name: str, x: float, y: float, *, kind: str = "facility") -> Row:
    """A place that is not a workstation (a facility's room, or a plain room)."""
    return {"id": place_id, "kind": kind, "name": name, "x": x, "y": y}


def desk_row(
    count: int, *, x0: float = 5.0, step: float = 4.0, y: float = 6.0
) -> list[tuple[float, float]]:
    """Where ``count`` workstations stand in one row along x."""
    return [(x0 + step * n, y) for n in range(count)]


def item(
    type_id: str,
    name: str,
    kind: str | None = None,
    *,
    synonyms: Sequence[str] = (),
    **flags: bool,
) -> Row:
    """An item type; ``kind`` (personal, electronic, product) left out for an ordinary one;
    ``flags``: signable, seals, consumable, mass."""
    row: Row = {"id": type_id, "name": name}
    if kind is not None:
        row["kind"] = kind
    row |= flags
    if synonyms:
        row["synonyms"] = list(synonyms)
    return row


def operation(
    op_id: str,
    *verbs: str,
    name: str | None = None,
    input: str | None = None,  # the office file's own word
    product: str | None = None,
    **more: Any,
) -> Row:
    """An operation named ``name`` (its id when not given) asked for with ``verbs``; ``more``:
    sends_out, destination_asked, consumes, done."""
    row: Row = {"id": op_id, "name": name or op_id}
    if verbs:
        row["verbs"] = list(verbs)
    if input is not None:
        row["input"] = input
    if product is not None:
        row["product"] = product
    return row | more


def facility(
    facility_id: str,
    name: str,
    *,
    at: str,
    guards: Sequence[str],
    operations: Sequence[str] = (),
    products: Sequence[str] = (),
    supplies: Iterable[Thing] = (),
    synonyms: Sequence[str] = (),
) -> Row:
    """A facility in room ``at`` that ``guards`` look after; ``supplies``: what it keeps for
    anyone."""
    row: Row = {"id": facility_id, "name": name}
    if synonyms:
        row["synonyms"] = list(synonyms)
    row |= {"location": at, "guards": list(guards)}
    if operations:
        row["operations"] = list(operations)
    if products:
        row["products"] = list(products)
    if supplies:
        row["supplies"] = _things(supplies)
    return row


@dataclass(frozen=True)
class Person:
    person_id: str
    name: str
    owns: tuple[Thing, ...]
    aliases: tuple[str, ...]
    at: str | None  # a place other than the person's own workstation


def person(
    person_id: str, name: str, *owns: Thing, aliases: Sequence[str] = (), at: str | None = None
) -> Person:
    """A colleague who owns ``owns`` (besides what everyone in the office owns)."""
    return Person(person_id, name, owns, tuple(aliases), at)


def office_file(
    name: str,
    people: Sequence[Person],
    *,
    rooms: Sequence[Row],
    item_types: Sequence[Row],
    operations: Sequence[Row],
    facilities: Sequence[Row],
    home: str,
    everyone_owns: Sequence[Thing] = (),
    desks: Sequence[tuple[float, float]] | None = None,
    desk_word: str = "desk",
    group: tuple[str, str] = ("all", "Everyone"),
    desk_for_everyone: bool = True,
) -> Row:
    """The office file: person n sits at workstation n (``{desk_word}_n``, at ``desks[n-1]``,
    a row along y=6 by default) unless placed elsewhere; ``desk_for_everyone`` False: a person
    placed elsewhere has no workstation, and the desks are numbered over the others only;
    ``group``: the id and name of the group of everyone; ``home``: where the robot waits."""
    seated = [p for p in people if desk_for_everyone or p.at is None]
    desk_of = {p.person_id: f"{desk_word}_{n}" for n, p in enumerate(seated, 1)}
    places = desks if desks is not None else desk_row(len(seated))
    workstations = [
        room(f"{desk_word}_{n}", f"{desk_word.capitalize()} {n}", x, y, kind="workstation")
        for n, (x, y) in enumerate(places, 1)
    ]
    group_id, group_name = group
    return copy.deepcopy(
        {
            "name": name,
            "locations": [*workstations, *rooms],
            "item_types": list(item_types),
            "operations": list(operations),
            "people": [
                {
                    "id": p.person_id,
                    "name": p.name,
                    "aliases": list(p.aliases),
                    "location": p.at or desk_of[p.person_id],
                    "handle": f"@{p.person_id}",
                    "owns": _things([*p.owns, *everyone_owns]),
                }
                for p in people
            ],
            "facilities": list(facilities),
            "groups": [
                {"id": group_id, "name": group_name, "members": [p.person_id for p in people]}
            ],
            "robot": {"home": home},
        }
    )


def parsed(raw: Callable[[], Row]) -> Callable[[], Office]:
    """The office ``raw`` describes, parsed once (offices are immutable)."""

    @functools.cache
    def office() -> Office:
        file = raw()
        return parse_office(file, file["name"])

    return office


def write_office(raw: Row, path: Path) -> Path:
    """``raw`` as an office file, for the command line (``--office``)."""
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return path
