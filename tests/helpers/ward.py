"""A hospital ward for the reader's tests of blind round 40's classes (the round's own offices
and sentences were never read): a label printer whose product is a patient label, rulers and
staplers several people own, an electronic file everyone has, and a colleague whose name has a
mark (Zoë). Patients in the beds are not people of the office."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("zoe", "Zoë Hart", "ruler", "stapler", aliases=["Zoe"]),
    ob.person("omar", "Omar Said", "ruler", "clipboard"),
    ob.person("pia", "Pia Lund", "stapler", "clipboard"),
    ob.person("kofi", "Kofi Mensah", "ruler"),
    ob.person("rhea", "Rhea Dunn", "clipboard"),
)


def raw_ward() -> dict[str, Any]:
    return ob.office_file(
        "ward",
        _PEOPLE,
        rooms=[
            ob.room("station", "Nurses' station", 4.0, 20.0),
            ob.room("sluice", "Sluice room", 14.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("ruler", "ruler"),
            ob.item("stapler", "stapler"),
            ob.item("clipboard", "clipboard"),
            ob.item("printout", "printout", "product"),
            ob.item("label", "label", "product", synonyms=["patient label", "wristband label"]),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("label", "tag", name="print labels", product="label"),
        ],
        facilities=[
            ob.facility("printer", "printer", at="station", guards=["rhea"], operations=["print"]),
            ob.facility(
                "label_printer",
                "label printer",
                at="station",
                guards=["rhea"],
                operations=["label"],
                products=["label"],
            ),
        ],
        everyone_owns=["file"],
        home="station",
    )


ward = ob.parsed(raw_ward)
