"""A hospital ward for the reader's tests of blind round 40's sending-service class (the
round's own office and sentences were never read): a pneumatic tube that sends a sample out of
the ward to a department, a doctor and a nurse, and forms and samples everyone has."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("kim", "Kim Hale", "pen"),
    ob.person("ames", "Dr Ames", "pen", aliases=["Ames", "Dr Ames"]),
    ob.person("ravi", "Ravi Nair", "clipboard"),
    ob.person("olu", "Olu Bade", "pen"),
)


def raw_tube_ward() -> dict[str, Any]:
    return ob.office_file(
        "tube ward",
        _PEOPLE,
        rooms=[
            ob.room("station", "Nurses' station", 4.0, 20.0),
            ob.room("sluice", "Sluice room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic"),
            ob.item("form", "form", "personal", signable=True),
            ob.item("sample", "sample", "personal", synonyms=["swab", "specimen"]),
            ob.item("pen", "pen"),
            ob.item("clipboard", "clipboard"),
        ],
        operations=[
            ob.operation(
                "tube",
                "tube",
                name="pneumatic tube",
                input="sample",
                sends_out=True,
                destination_asked="which department",
            ),
        ],
        facilities=[
            ob.facility(
                "tube_station",
                "tube station",
                at="sluice",
                guards=["ravi"],
                operations=["tube"],
                synonyms=["pneumatic tube", "tube"],
            ),
        ],
        everyone_owns=["file", "form", "sample"],
        home="station",
    )


tube_ward = ob.parsed(raw_tube_ward)
