"""A small production office for the reader's tests of round 166's classes (the round's own
offices and sentences were never read). A workshop sharpens clippers and a laminator
laminates badges; a laundry washes costumes; the ingest desk in the edit suite ingests a
camera card; the kit counter charges a camera battery and keeps AA batteries and a tape
measure (for measuring) for anyone. Colleagues own clippers, folders (signable), badges,
camera batteries, camera cards, lapel microphones and spreadsheets."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_OWN = ("clippers", "folder", "badge", "camera_battery", "camera_card", "spreadsheet", "lav_mic")

_PEOPLE = (
    ob.person("ana", "Ana Ruiz", *_OWN),
    ob.person("sam", "Sam Okoye", *_OWN),
    ob.person("frank", "Frank Osei", "camera_card", at="edit_suite"),
    ob.person("gus", "Gus Brandt", "clippers", at="workshop"),
    ob.person("dev", "Devika Rao", "badge", at="kit_room"),
    ob.person("wren", "Wren Hale", "folder", at="wardrobe"),
)


def raw_kit_room() -> dict[str, Any]:
    return ob.office_file(
        "kit room",
        _PEOPLE,
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.5),
            ob.room("edit_suite", "Edit suite", 11.0, 20.5),
            ob.room("kit_room", "Kit room", 18.0, 20.5),
            ob.room("wardrobe", "Wardrobe", 25.0, 20.5),
        ],
        item_types=[
            ob.item("clippers", "clippers", synonyms=["hair clippers"]),
            ob.item("folder", "folder", "personal", signable=True),
            ob.item("badge", "badge", "personal", synonyms=["id badge"]),
            ob.item("camera_battery", "camera battery", synonyms=["battery pack"]),
            ob.item(
                "aa_batteries", "AA batteries", consumable=True, synonyms=["aa battery", "batts"]
            ),
            ob.item("lav_mic", "lapel microphone"),
            ob.item("spare_mics", "handheld mics", synonyms=["mics"]),
            ob.item("camera_card", "camera card", "personal", synonyms=["memory card"]),
            ob.item("spreadsheet", "spreadsheet", "electronic", synonyms=["sheet"]),
            ob.item("costume", "costume", synonyms=["costumes"]),
            {"id": "tape_measure", "name": "tape measure", "purposes": ["measure"]},
        ],
        operations=[
            ob.operation("sharpen", "sharpen", "hone", input="clippers"),
            ob.operation("laminate", "laminate", input="badge"),
            ob.operation("wash", "wash", "launder", input="costume"),
            ob.operation("ingest", "ingest", "offload", input="camera_card"),
            ob.operation("charge", "charge", "recharge", input="camera_battery"),
        ],
        facilities=[
            ob.facility(
                "sharpener",
                "sharpening bench",
                at="workshop",
                guards=["gus"],
                operations=["sharpen"],
            ),
            ob.facility(
                "laminator", "laminator", at="workshop", guards=["gus"], operations=["laminate"]
            ),
            ob.facility("laundry", "laundry", at="wardrobe", guards=["wren"], operations=["wash"]),
            ob.facility(
                "ingest_desk",
                "ingest desk",
                at="edit_suite",
                guards=["frank"],
                operations=["ingest"],
            ),
            ob.facility(
                "kit_counter",
                "kit counter",
                at="kit_room",
                guards=["dev"],
                operations=["charge"],
                supplies=["aa_batteries", "tape_measure", "spare_mics"],
            ),
        ],
        home="workshop",
    )


kit_room = ob.parsed(raw_kit_room)
