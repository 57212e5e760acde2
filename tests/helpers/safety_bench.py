"""A small workshop office for the reader's tests of round 186's classes (the round's own offices
and sentences were never read): colleagues own gloves, safety goggles, mugs, staplers and
scissors (for cutting); the stores keep plasters (for cuts), grip tape (for cut fingers), hand
cream (for sore hands), chalk (for grip) and spare gloves for anyone; a scale room weighs
samples and a print room prints files."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Ming", "gloves", "goggles", "mug", "stapler"),
    ob.person("ros", "Ros Tait", "gloves", "goggles", "mug", "scissors"),
    ob.person("nat", "Nat Obi", "gloves", "mug", "stapler"),
    ob.person("ivo", "Ivo Karl", "goggles", at="stores"),
)


def raw_safety_bench() -> dict[str, Any]:
    return ob.office_file(
        "safety bench",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Stores", 4.0, 20.0),
            ob.room("scale_room", "Scale room", 12.0, 20.0),
            ob.room("print_room", "Print room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("gloves", "gloves", synonyms=["work gloves"]),
            ob.item("goggles", "safety goggles", synonyms=["goggles"]),
            ob.item("mug", "mug", synonyms=["cup"]),
            {"id": "stapler", "name": "stapler", "purposes": ["staple"]},
            {"id": "scissors", "name": "scissors", "purposes": ["cut", "trim"]},
            {"id": "plasters", "name": "plasters", "consumable": True, "purposes": ["cover cuts"]},
            {
                "id": "hand_cream",
                "name": "hand cream",
                "consumable": True,
                "purposes": ["soothe sore hands"],
            },
            {"id": "chalk", "name": "chalk", "consumable": True, "purposes": ["grip"]},
            {"id": "tape", "name": "grip tape", "purposes": ["wrap cut fingers"]},
            ob.item("sample", "sample"),
            ob.item("file", "file", "electronic"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("weigh", "weigh", input="sample"),
            ob.operation("print", "print", input="file", product="printout"),
        ],
        facilities=[
            ob.facility(
                "store_counter",
                "store counter",
                at="stores",
                guards=["ivo"],
                supplies=["plasters", "hand_cream", "chalk", "gloves", "tape"],
            ),
            ob.facility("scale", "scale", at="scale_room", guards=["ivo"], operations=["weigh"]),
            ob.facility(
                "printer", "printer", at="print_room", guards=["ivo"], operations=["print"]
            ),
        ],
        everyone_owns=["file", "sample"],
        home="stores",
    )


safety_bench = ob.parsed(raw_safety_bench)
