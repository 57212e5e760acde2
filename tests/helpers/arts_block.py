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
from helpers import office_builder as ob

_PEOPLE = (
    ob.person("marta", "Marta Quigley", "stopwatch", "banner"),
    ob.person("ewan", "Ewan Holt", "tape_measure", "poster"),
    ob.person("priya", "Priya Natt", "tunic", "portfolio", at="dance_studio"),
    ob.person("colm", "Colm Reddy", "stopwatch", "scripts"),
    ob.person("hatty", "Hatty Lowe", "tunic", "poster"),
    ob.person("bram", "Bram Osei", "scripts", "portfolio"),
    ob.person("ola", "Ola Brennan", "poster", at="music_room"),
    ob.person("finn", "Finn Darby", "stopwatch", at="music_room"),
)


def raw_arts_block() -> dict[str, Any]:
    return ob.office_file(
        "arts_block",
        _PEOPLE,
        desks=ob.desk_row(5, x0=4.0, y=5.0),
        desk_for_everyone=False,
        rooms=[
            ob.room("music_room", "Music room", 30.0, 5.0, kind="workstation"),
            ob.room("dance_studio", "Dance studio", 26.0, 5.0, kind="room"),
            ob.room("wardrobe", "Wardrobe store", 4.0, 18.0),
            ob.room("art_room", "Art room", 10.0, 18.0),
            ob.room("scenery_dock", "Scenery dock", 16.0, 18.0),
            ob.room("print_unit", "Reprographics", 22.0, 18.0),
            ob.room("exams_office", "Exams office", 28.0, 18.0),
            ob.room("prep_room", "Prep room", 34.0, 18.0),
            ob.room("staff_room", "Staff room", 34.0, 5.0, kind="room"),
            ob.room("kitchen", "Kitchen", 40.0, 18.0),
        ],
        item_types=[
            ob.item("stopwatch", "stopwatch"),
            ob.item("tape_measure", "tape measure"),
            ob.item("stapler", "stapler"),
            ob.item("cable_ties", "cable ties", consumable=True),
            ob.item("tunic", "tunic", "personal", synonyms=["costume"]),
            ob.item("banner", "banner", "personal", synonyms=["backdrop"]),
            ob.item("poster", "poster", "personal"),
            ob.item("portfolio", "portfolio", "personal", synonyms=["folder"]),
            ob.item("scripts", "exam scripts", "personal", synonyms=["scripts"]),
            ob.item("coffee", "coffee", "product"),
        ],
        operations=[
            ob.operation("press", "press", input="tunic"),
            ob.operation("crop", "crop", input="poster"),
            ob.operation("fireproof", "fireproof", input="banner"),
            ob.operation("dye", "dye", input="tunic"),
            ob.operation("bind", "bind", input="portfolio"),
            ob.operation("brew", "make", name="make coffee", product="coffee"),
            ob.operation(
                "post_out",
                "post",
                name="post",
                input="scripts",
                sends_out=True,
                destination_asked="which exam board they go to",
            ),
            ob.operation(
                "launder",
                "launder",
                input="tunic",
                sends_out=True,
                destination_asked="which laundry it goes to",
            ),
        ],
        facilities=[
            ob.facility(
                "hot_press",
                "hot press",
                at="wardrobe",
                guards=["hatty"],
                operations=["press", "launder"],
            ),
            ob.facility(
                "guillotine", "guillotine", at="art_room", guards=["ewan"], operations=["crop"]
            ),
            ob.facility(
                "dye_bench",
                "dye bench",
                at="scenery_dock",
                guards=["bram"],
                operations=["fireproof", "dye"],
            ),
            ob.facility(
                "comb_binder", "comb binder", at="print_unit", guards=["colm"], operations=["bind"]
            ),
            ob.facility(
                "exams_desk",
                "exams desk",
                at="exams_office",
                guards=["marta"],
                operations=["post_out"],
            ),
            ob.facility(
                "prep_shelves",
                "prep shelves",
                at="prep_room",
                guards=["colm"],
                supplies=["tape_measure", "cable_ties"],
            ),
            ob.facility(
                "art_cupboard",
                "art cupboard",
                at="art_room",
                guards=["ewan"],
                supplies=["cable_ties"],
            ),
            ob.facility(
                "staff_shelf", "staff shelf", at="staff_room", guards=["bram"], supplies=["stapler"]
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["bram"],
                operations=["brew"],
                products=["coffee"],
            ),
        ],
        home="kitchen",
        group=("arts", "Arts"),
    )


arts_block = ob.parsed(raw_arts_block)


@functools.cache
def arts_block_dry_cleaning() -> Office:
    """The same arts block whose wardrobe sends costumes out to be dry cleaned (verb "dry
    clean", a phrase of two words) instead of laundered."""
    raw = raw_arts_block()
    for op in raw["operations"]:
        if op["id"] == "launder":
            op["verbs"], op["name"] = ["dry clean"], "dry clean"
    return parse_office(raw, "arts_block_dry_cleaning")
