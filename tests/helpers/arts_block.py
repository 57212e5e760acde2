"""A school's arts block for the reader's tests of blind round 17's classes (the round's own
office and sentences were never read).

Teachers sit at desks; one (Priya) works in the dance studio, a room with no facility, where
nothing is kept. A wardrobe store runs a hot press (operation ``press``); the art room's
guillotine crops (operation id ``crop``, verb "crop"); the scenery dock fireproofs
(``fireproof``) and dyes (``dye``) fabric; reprographics ("Reprographics", people say
"repro") has a comb binder (``bind``); the exams office posts scripts out to exam boards and
the wardrobe store sends costumes out to be laundered (both ``sends_out``). The science prep
room keeps a spare tape measure and cable ties for anyone; the staff room keeps the
department stapler; the kitchen makes coffee."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("marta", "Marta Quigley", "desk_1", [{"type": "stopwatch"}, {"type": "banner"}]),
    ("ewan", "Ewan Holt", "desk_2", [{"type": "tape_measure"}, {"type": "poster"}]),
    ("priya", "Priya Natt", "dance_studio", [{"type": "tunic"}, {"type": "portfolio"}]),
    ("colm", "Colm Reddy", "desk_3", [{"type": "stopwatch"}, {"type": "scripts"}]),
    ("hatty", "Hatty Lowe", "desk_4", [{"type": "tunic"}, {"type": "poster"}]),
    ("bram", "Bram Osei", "desk_5", [{"type": "scripts"}, {"type": "portfolio"}]),
    ("ola", "Ola Brennan", "music_room", [{"type": "poster"}]),
    ("finn", "Finn Darby", "music_room", [{"type": "stopwatch"}]),
)


def raw_arts_block() -> dict[str, Any]:
    return {
        "name": "arts_block",
        "locations": [
            *(
                {
                    "id": f"desk_{n}",
                    "kind": "workstation",
                    "name": f"Desk {n}",
                    "x": 4.0 * n,
                    "y": 5.0,
                }
                for n in range(1, 6)
            ),
            {"id": "music_room", "kind": "workstation", "name": "Music room", "x": 30.0, "y": 5.0},
            {"id": "dance_studio", "kind": "room", "name": "Dance studio", "x": 26.0, "y": 5.0},
            {"id": "wardrobe", "kind": "facility", "name": "Wardrobe store", "x": 4.0, "y": 18.0},
            {"id": "art_room", "kind": "facility", "name": "Art room", "x": 10.0, "y": 18.0},
            {
                "id": "scenery_dock",
                "kind": "facility",
                "name": "Scenery dock",
                "x": 16.0,
                "y": 18.0,
            },
            {"id": "print_unit", "kind": "facility", "name": "Reprographics", "x": 22.0, "y": 18.0},
            {
                "id": "exams_office",
                "kind": "facility",
                "name": "Exams office",
                "x": 28.0,
                "y": 18.0,
            },
            {"id": "prep_room", "kind": "facility", "name": "Prep room", "x": 34.0, "y": 18.0},
            {"id": "staff_room", "kind": "room", "name": "Staff room", "x": 34.0, "y": 5.0},
            {"id": "kitchen", "kind": "facility", "name": "Kitchen", "x": 40.0, "y": 18.0},
        ],
        "item_types": [
            {"id": "stopwatch", "name": "stopwatch"},
            {"id": "tape_measure", "name": "tape measure"},
            {"id": "stapler", "name": "stapler"},
            {"id": "cable_ties", "name": "cable ties", "consumable": True},
            {"id": "tunic", "name": "tunic", "kind": "personal", "synonyms": ["costume"]},
            {"id": "banner", "name": "banner", "kind": "personal", "synonyms": ["backdrop"]},
            {"id": "poster", "name": "poster", "kind": "personal"},
            {"id": "portfolio", "name": "portfolio", "kind": "personal", "synonyms": ["folder"]},
            {"id": "scripts", "name": "exam scripts", "kind": "personal", "synonyms": ["scripts"]},
            {"id": "coffee", "name": "coffee", "kind": "product"},
        ],
        "operations": [
            {"id": "press", "name": "press", "verbs": ["press"], "input": "tunic"},
            {"id": "crop", "name": "crop", "verbs": ["crop"], "input": "poster"},
            {"id": "fireproof", "name": "fireproof", "verbs": ["fireproof"], "input": "banner"},
            {"id": "dye", "name": "dye", "verbs": ["dye"], "input": "tunic"},
            {"id": "bind", "name": "bind", "verbs": ["bind"], "input": "portfolio"},
            {"id": "brew", "name": "make coffee", "verbs": ["make"], "product": "coffee"},
            {
                "id": "post_out",
                "name": "post",
                "verbs": ["post"],
                "input": "scripts",
                "sends_out": True,
                "destination_asked": "which exam board they go to",
            },
            {
                "id": "launder",
                "name": "launder",
                "verbs": ["launder"],
                "input": "tunic",
                "sends_out": True,
                "destination_asked": "which laundry it goes to",
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": [],
                "location": where,
                "handle": f"@{pid}",
                "owns": owns,
            }
            for pid, name, where, owns in _PEOPLE
        ],
        "facilities": [
            {
                "id": "hot_press",
                "name": "hot press",
                "location": "wardrobe",
                "operations": ["press", "launder"],
                "guards": ["hatty"],
            },
            {
                "id": "guillotine",
                "name": "guillotine",
                "location": "art_room",
                "operations": ["crop"],
                "guards": ["ewan"],
            },
            {
                "id": "dye_bench",
                "name": "dye bench",
                "location": "scenery_dock",
                "operations": ["fireproof", "dye"],
                "guards": ["bram"],
            },
            {
                "id": "comb_binder",
                "name": "comb binder",
                "location": "print_unit",
                "operations": ["bind"],
                "guards": ["colm"],
            },
            {
                "id": "exams_desk",
                "name": "exams desk",
                "location": "exams_office",
                "operations": ["post_out"],
                "guards": ["marta"],
            },
            {
                "id": "prep_shelves",
                "name": "prep shelves",
                "location": "prep_room",
                "guards": ["colm"],
                "supplies": [{"type": "tape_measure"}, {"type": "cable_ties"}],
            },
            {
                "id": "art_cupboard",
                "name": "art cupboard",
                "location": "art_room",
                "guards": ["ewan"],
                "supplies": [{"type": "cable_ties"}],
            },
            {
                "id": "staff_shelf",
                "name": "staff shelf",
                "location": "staff_room",
                "guards": ["bram"],
                "supplies": [{"type": "stapler"}],
            },
            {
                "id": "coffee_machine",
                "name": "coffee machine",
                "location": "kitchen",
                "operations": ["brew"],
                "products": ["coffee"],
                "guards": ["bram"],
            },
        ],
        "groups": [{"id": "arts", "name": "Arts", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "kitchen"},
    }


@functools.cache
def arts_block() -> Office:
    return parse_office(raw_arts_block(), "arts_block")


@functools.cache
def arts_block_dry_cleaning() -> Office:
    """The same arts block whose wardrobe sends costumes out to be dry cleaned (verb "dry
    clean", a phrase of two words) instead of laundered."""
    raw = raw_arts_block()
    for op in raw["operations"]:
        if op["id"] == "launder":
            op["verbs"], op["name"] = ["dry clean"], "dry clean"
    return parse_office(raw, "arts_block_dry_cleaning")
