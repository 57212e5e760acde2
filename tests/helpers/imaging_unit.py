"""A small imaging unit for the reader's tests of places named by the last word of their name
("take it down to the studio" for the "Imaging studio"): an imaging studio with a scanner, a
loading bay, a staff kitchen, a security post, two meeting rooms told apart by a letter, and
letters and a camera people own."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Lindqvist", "letter", "camera"),
    ob.person("tobi", "Tobi Adewale", "letter"),
    ob.person("marta", "Marta Quental", "letter", "camera"),
    ob.person("oskar", "Oskar Brenner", "letter"),
)


def raw_imaging_unit() -> dict[str, Any]:
    return ob.office_file(
        "imaging",
        _PEOPLE,
        rooms=[
            ob.room("imaging_studio", "Imaging studio", 17.0, 20.5),
            ob.room("loading_bay", "Loading bay", 4.0, 20.5),
            ob.room("staff_kitchen", "Staff kitchen", 20.0, 20.5),
            ob.room("security_post", "Security post", 12.0, 20.5),
            ob.room("meeting_a", "Meeting room A", 8.0, 20.5),
            ob.room("meeting_b", "Meeting room B", 10.0, 20.5),
        ],
        item_types=[
            ob.item("letter", "letter", "personal"),
            ob.item("camera", "camera"),
            ob.item("scan_copy", "scan", "product"),
        ],
        operations=[
            ob.operation("scan", "scan", "digitise", input="letter", product="scan_copy"),
        ],
        facilities=[
            ob.facility(
                "scanner",
                "scanner",
                at="imaging_studio",
                guards=["oskar"],
                operations=["scan"],
                products=["scan_copy"],
            ),
        ],
        home="staff_kitchen",
    )


imaging_unit = ob.parsed(raw_imaging_unit)
