"""A small veterinary clinic the reader's tests of this round run on: no sentence of the
default office fits it. Several people are named with ordinary words or a month (Dawn, Rich,
May, Hal, Chip, whose name is also in an item's), a fridge keeps an ice pack, a printer
makes printouts."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("dawn", "Dawn Ellis", "thermometer", "document"),
    ob.person("rich", "Rich Adeyemi", "clipboard", "document", aliases=["Manager Rich"]),
    ob.person("may", "May Oduya", ob.kept("ice_pack", at="staff_room", facility="fridge")),
    ob.person("hal", "Hal Brooks", "thermometer", "document"),
    ob.person("ines", "Inés Vidal", "clipboard", "document"),
    ob.person("tomas", "Tomás Reyes", "document"),
    ob.person("chip", "Chip Moreno", "chip_scanner", "document"),
)


def raw_clinic() -> dict[str, Any]:
    return ob.office_file(
        "clinic",
        _PEOPLE,
        everyone_owns=["file"],
        rooms=[
            ob.room("print_corner", "Print corner", 4.0, 20.5),
            ob.room("staff_room", "Staff room", 11.0, 20.5),
        ],
        item_types=[
            ob.item("thermometer", "thermometer"),
            ob.item("clipboard", "clipboard"),
            ob.item("chip_scanner", "microchip scanner", synonyms=["chip reader"]),
            ob.item("ice_pack", "ice pack", "personal"),
            ob.item("document", "document", "personal", synonyms=["form"]),
            ob.item("file", "file", "electronic", synonyms=["rota"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[ob.operation("print", "print", input="file", product="printout")],
        facilities=[
            ob.facility(
                "printer", "printer", at="print_corner", guards=["tomas"], operations=["print"]
            ),
            ob.facility("fridge", "fridge", at="staff_room", guards=["hal"]),
        ],
        home="print_corner",
    )


clinic = ob.parsed(raw_clinic)
