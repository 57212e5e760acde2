"""A school staff room for the tests of blind rounds 57-58's classes (the rounds' own offices
and sentences were never read): teachers addressed by title and surname ("Ms Okafor", "Mr
Lindqvist"), a print room whose print operation is asked for by phrasal verbs ("print off",
"print out"), and a stationery cupboard."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("tess", "Tess Moran", "stapler", aliases=["Ms Moran"]),
    ob.person("ada", "Ada Okafor", "stapler", aliases=["Ms Okafor"]),
    ob.person("nils", "Nils Lindqvist", "hole_punch", aliases=["Mr Lindqvist"]),
    ob.person("priya", "Priya Shah", aliases=["Mrs Shah"], at="print_room"),
    ob.person("colm", "Colm Brady", "stapler", aliases=["Mr Brady"]),
)


def raw_staff_room() -> dict[str, Any]:
    return ob.office_file(
        "staff_room",
        _PEOPLE,
        everyone_owns=["worksheet"],
        rooms=[ob.room("print_room", "Print room", 4.0, 20.0)],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("hole_punch", "hole punch"),
            ob.item("worksheet", "worksheet", "electronic", synonyms=["file", "lesson plan"]),
            ob.item("printout", "printout", "product", synonyms=["print"]),
            ob.item("paper", "paper", consumable=True),
        ],
        operations=[
            ob.operation(
                "print", "print", "print off", "print out", input="worksheet", product="printout"
            ),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["priya"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "cupboard",
                "stationery cupboard",
                at="print_room",
                guards=["priya"],
                supplies=["paper"],
            ),
        ],
        home="print_room",
    )


staff_room = ob.parsed(raw_staff_room)
