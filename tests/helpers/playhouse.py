"""A theatre company's production office for the reader's tests of blind round 8's classes
(the round's own office and sentences were never read). Two pairs of people whose one-word
names sound alike (Ann Mbeki and Roseanne Vale, called Anne; Jon Petrov and Jonathan Wilde,
called John), paper contracts that are copied, couriered and faxed out, a props cupboard
that keeps cotton gloves and gaffer tape for anyone, and places that are neither people nor
facilities (the green room, the stage door)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("ann", "Ann Mbeki", [], [{"type": "torch"}, {"type": "contract"}]),
    ("roseanne", "Roseanne Vale", ["Anne"], [{"type": "tape_measure"}, {"type": "contract"}]),
    ("jon", "Jon Petrov", [], [{"type": "torch"}, {"type": "contract"}, {"type": "lanyard"}]),
    ("jonathan", "Jonathan Wilde", ["John"], [{"type": "lanyard"}, {"type": "contract"}]),
    ("oona", "Oona Beck", [], [{"type": "tape_measure"}, {"type": "contract"}]),
    ("dev", "Dev Kapoor", ["Devraj"], [{"type": "torch"}, {"type": "contract"}]),
)


def raw_playhouse() -> dict[str, Any]:
    return {
        "name": "playhouse",
        "locations": [
            *(
                {
                    "id": f"desk_{n}",
                    "kind": "workstation",
                    "name": f"Desk {n}",
                    "x": 4.0 * n,
                    "y": 5.0,
                }
                for n in range(1, len(_PEOPLE) + 1)
            ),
            {"id": "print_nook", "kind": "facility", "name": "Print nook", "x": 4.0, "y": 18.0},
            {"id": "store_room", "kind": "facility", "name": "Store room", "x": 12.0, "y": 18.0},
            {"id": "stage_door", "kind": "facility", "name": "Stage door", "x": 20.0, "y": 18.0},
            {"id": "green_room", "kind": "room", "name": "Green room", "x": 28.0, "y": 18.0},
        ],
        "item_types": [
            {"id": "torch", "name": "torch", "synonyms": ["flashlight"]},
            {"id": "tape_measure", "name": "tape measure"},
            {"id": "lanyard", "name": "lanyard", "synonyms": ["pass"]},
            {"id": "cotton_gloves", "name": "cotton gloves", "synonyms": ["white gloves"]},
            {"id": "gaffer_tape", "name": "gaffer tape", "consumable": True, "mass": True},
            {
                "id": "contract",
                "name": "contract",
                "kind": "personal",
                "signable": True,
                "synonyms": ["agreement", "rider"],
            },
            {"id": "rota", "name": "rota", "kind": "electronic", "synonyms": ["schedule"]},
            {"id": "printout", "name": "printout", "kind": "product"},
            {"id": "copy", "name": "photocopy", "kind": "product", "synonyms": ["copy"]},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "rota",
                "product": "printout",
            },
            {
                "id": "copy",
                "name": "copy",
                "verbs": ["copy", "photocopy"],
                "input": "contract",
                "product": "copy",
            },
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier"],
                "input": "contract",
                "sends_out": True,
            },
            {
                "id": "fax",
                "name": "fax",
                "verbs": ["fax"],
                "input": "contract",
                "sends_out": True,
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "rota"}],
            }
            for n, (pid, name, aliases, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "copier",
                "name": "copier",
                "location": "print_nook",
                "operations": ["print", "copy"],
                "guards": ["oona"],
            },
            {
                "id": "props_cupboard",
                "name": "props cupboard",
                "synonyms": ["cupboard"],
                "location": "store_room",
                "guards": ["dev"],
                "supplies": [{"type": "cotton_gloves"}, {"type": "gaffer_tape"}],
            },
            {
                "id": "courier_desk",
                "name": "courier desk",
                "location": "stage_door",
                "operations": ["courier"],
                "guards": ["jon"],
            },
            {
                "id": "fax_machine",
                "name": "fax machine",
                "location": "print_nook",
                "operations": ["fax"],
                "guards": ["oona"],
            },
        ],
        "groups": [{"id": "company", "name": "Company", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "print_nook"},
    }


@functools.cache
def playhouse() -> Office:
    return parse_office(raw_playhouse(), "playhouse")
