"""A small office whose courier desk sends documents out and whose own words are also words of
English place names, for the reader's tests of an outside address said in comma-separated
parts (reading/address_run.py): a garden tap that waters plants ("water"), a print room
("print"), a pepper mill ("mill") and a colleague called Will. No sentence or name of a
measured office is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("will", "Will Brandt", aliases=["Will"]),
    ob.person("ines", "Ines Faro"),
    ob.person("olu", "Olu Bakare"),
    ob.person("greta", "Greta Lund", "pepper_mill"),
)


def raw_courier_yard() -> dict[str, Any]:
    return ob.office_file(
        "courier yard",
        _PEOPLE,
        rooms=[
            ob.room("dispatch", "Dispatch", 4.0, 20.0),
            ob.room("print_room", "Print room", 12.0, 20.0),
            ob.room("garden", "Garden", 20.0, 20.0),
        ],
        item_types=[
            ob.item(
                "document",
                "document",
                "personal",
                synonyms=["contract", "letter", "invoice", "form"],
            ),
            ob.item("plant", "plant"),
            ob.item("pepper_mill", "pepper mill", synonyms=["mill"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                name="send by courier",
                input="document",
                sends_out=True,
            ),
            ob.operation("print", "print", input="document", product="printout"),
            ob.operation("water", "water", input="plant"),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="dispatch",
                guards=["olu"],
                operations=["courier"],
            ),
            ob.facility(
                "print_room",
                "print room",
                at="print_room",
                guards=["olu"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "garden_tap", "garden tap", at="garden", guards=["ines"], operations=["water"]
            ),
        ],
        everyone_owns=["document"],
        home="dispatch",
    )


courier_yard = ob.parsed(raw_courier_yard)
