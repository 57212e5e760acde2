"""A riding school's tack room for the reader's tests of fixer 186d's classes (written without
the testers' names): colleagues whose names are also English words (Isla Bell, Amber Shaw,
Patience Okoro), a case opener Isla owns, an accord Amber and the speaker each own, harnesses
an inspection bench inspects, and costumes a sewing room mends; a cold room keeps things."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Ming", "harness", "costume", "accord", "mug"),
    ob.person("isla", "Isla Bell", "case_opener", "harness", "mug"),
    ob.person("amber", "Amber Shaw", "accord", "costume", "mug"),
    ob.person("patience", "Patience Okoro", "harness", "mug"),
    ob.person("tom", "Tom Reid", "mug"),
)


def raw_tack_room() -> dict[str, Any]:
    return ob.office_file(
        "tack room",
        _PEOPLE,
        rooms=[
            ob.room("inspection_bay", "Inspection bay", 24.0, 18.0),
            ob.room("sewing_room", "Sewing room", 8.0, 18.0),
            ob.room("cold_room", "Cold room", 16.0, 18.0, kind="room"),
        ],
        item_types=[
            ob.item("harness", "harness", "personal", synonyms=["tack"]),
            ob.item("costume", "costume", "personal"),
            ob.item("accord", "accord", "personal"),
            ob.item("case_opener", "case opener") | {"purposes": ["open cases"]},
            ob.item("mug", "mug", synonyms=["cup"]),
            ob.item("report", "inspection report", "product"),
        ],
        operations=[
            ob.operation("inspect", "inspect", "check", input="harness", product="report"),
            ob.operation("mend", "mend", "repair", "fix", input="costume"),
        ],
        facilities=[
            ob.facility(
                "inspection_bench",
                "inspection bench",
                at="inspection_bay",
                guards=["tom"],
                operations=["inspect"],
                products=["report"],
            ),
            ob.facility(
                "sewing_machine",
                "sewing machine",
                at="sewing_room",
                guards=["tom"],
                operations=["mend"],
            ),
        ],
        home="inspection_bay",
    )


tack_room = ob.parsed(raw_tack_room)
