"""A small veterinary clinic the reader's tests of this round run on: no sentence of the
default office fits it. Several people are named with ordinary words or a month (Dawn, Rich,
May, Hal, Chip, whose name is also in an item's), a fridge keeps an ice pack, a printer
makes printouts."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    facility,
    item,
    kept,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("dawn", "Dawn Ellis", "thermometer", "document"),
    person("rich", "Rich Adeyemi", "clipboard", "document", aliases=["Manager Rich"]),
    person("may", "May Oduya", kept("ice_pack", at="staff_room", facility="fridge")),
    person("hal", "Hal Brooks", "thermometer", "document"),
    person("ines", "Inés Vidal", "clipboard", "document"),
    person("tomas", "Tomás Reyes", "document"),
    person("chip", "Chip Moreno", "chip_scanner", "document"),
)


def raw_clinic() -> dict[str, Any]:
    return office_file(
        "clinic",
        _PEOPLE,
        everyone_owns=["file"],
        rooms=[
            room("print_corner", "Print corner", 4.0, 20.5),
            room("staff_room", "Staff room", 11.0, 20.5),
        ],
        item_types=[
            item("thermometer", "thermometer"),
            item("clipboard", "clipboard"),
            item("chip_scanner", "microchip scanner", synonyms=["chip reader"]),
            item("ice_pack", "ice pack", "personal"),
            item("document", "document", "personal", synonyms=["form"]),
            item("file", "file", "electronic", synonyms=["rota"]),
            item("printout", "printout", "product"),
        ],
        operations=[operation("print", "print", input="file", product="printout")],
        facilities=[
            facility(
                "printer", "printer", at="print_corner", guards=["tomas"], operations=["print"]
            ),
            facility("fridge", "fridge", at="staff_room", guards=["hal"]),
        ],
        home="print_corner",
    )


clinic = parsed(raw_clinic)
