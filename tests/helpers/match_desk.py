"""A sports picture desk for the reader's tests of blind rounds 61-62's statement classes (the
rounds' own offices and sentences were never read): two colleagues who share a first name
(Owen Abbott, Owen Marsh), a name typed with diacritics (Björn Åkesson) and a hyphenated one
(Jean-Luc Ricard, "JL"), a colleague whose name is also a word of a thing (Olive, beside olive oil),
a seal, a shredder, a kettle, a staff fridge, a vending machine, a coffee machine and a kit
cabinet that keeps batteries."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("jeanluc", "Jean-Luc Ricard", "stapler", aliases=["Jean-Luc", "JL"]),
    ob.person("bjorn", "Björn Åkesson", "stapler", "seal", aliases=["Björn"]),
    ob.person("owena", "Owen Abbott", "flashgun"),
    ob.person("owenm", "Owen Marsh", "flashgun", "stapler"),
    ob.person("olive", "Olive Tran", "seal", aliases=["Olive"]),
    ob.person("dara", "Dara Quinn", "stapler", aliases=["Dara"]),
)


def raw_match_desk() -> dict[str, Any]:
    return ob.office_file(
        "match desk",
        _PEOPLE,
        everyone_owns=["layout", "invoice"],
        rooms=[
            ob.room("kit_room", "Kit room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 12.0, 20.0),
            ob.room("back_office", "Back office", 20.0, 20.0),
        ],
        item_types=[
            ob.item("layout", "layout", "electronic", synonyms=["page layout"]),
            ob.item("invoice", "invoice", "personal", signable=True),
            ob.item("stapler", "stapler"),
            ob.item("seal", "seal", seals=True, synonyms=["stamp"]),
            ob.item("flashgun", "flashgun", synonyms=["flash"]),
            ob.item("batteries", "batteries", consumable=True, synonyms=["battery"]),
            ob.item("oat_milk", "oat milk", consumable=True),
            ob.item("olive_oil", "olive oil", consumable=True),
            ob.item("snack", "snack", consumable=True, synonyms=["crisps"]),
            ob.item("coffee", "coffee", "product"),
            ob.item("tea", "tea", "product"),
        ],
        operations=[
            ob.operation("shred", "shred", input="invoice", consumes=True),
            ob.operation("brew", "brew", name="make coffee", product="coffee"),
            ob.operation("boil", "boil", name="make tea", product="tea"),
        ],
        facilities=[
            ob.facility(
                "shredder", "shredder", at="back_office", guards=["dara"], operations=["shred"]
            ),
            ob.facility(
                "kettle",
                "kettle",
                at="kitchen",
                guards=["dara"],
                operations=["boil"],
                products=["tea"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["dara"],
                operations=["brew"],
                products=["coffee"],
            ),
            ob.facility(
                "fridge",
                "staff fridge",
                at="kitchen",
                guards=["dara"],
                synonyms=["fridge"],
                supplies=["oat_milk", "olive_oil"],
            ),
            ob.facility(
                "vending", "vending machine", at="kitchen", guards=["dara"], supplies=["snack"]
            ),
            ob.facility(
                "kit_cabinet", "kit cabinet", at="kit_room", guards=["dara"], supplies=["batteries"]
            ),
        ],
        home="kit_room",
    )


match_desk = ob.parsed(raw_match_desk)
