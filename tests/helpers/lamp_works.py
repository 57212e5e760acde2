"""A lamp repair workshop for the reader's tests of blind rounds 59-64's classes of wanting and
of a spare asked for after a complaint (the rounds' own offices and sentences were never
read): a torch and a charger several people own, a mouse only one colleague has, tape kept in
a supply cupboard for anyone, and an espresso machine that makes cappuccinos."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("odile", "Odile Brann", "torch", "charger", "mouse"),
    ob.person("ginger", "Ginger Holm", "charger", "torch", aliases=["Ginger"]),
    ob.person("piet", "Piet Sandor", "charger", "stapler"),
    ob.person("wren", "Wren Calloway", "stapler", "mouse"),
    ob.person("rafe", "Rafe Donnel", "clipboard"),
)


def raw_lamp_works() -> dict[str, Any]:
    return ob.office_file(
        "lamp works",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Store room", 4.0, 20.0),
            ob.room("galley", "Galley", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("torch", "torch", synonyms=["flashlight"]),
            ob.item("charger", "charger"),
            ob.item("mouse", "mouse"),
            ob.item("stapler", "stapler"),
            ob.item("clipboard", "clipboard"),
            ob.item("tape", "roll of tape", consumable=True, synonyms=["tape"]),
            ob.item("cappuccino", "cappuccino", "product"),
        ],
        operations=[
            ob.operation("brew", "make", "brew", name="make cappuccino", product="cappuccino"),
        ],
        facilities=[
            ob.facility(
                "supply_cupboard",
                "supply cupboard",
                at="stores",
                guards=["rafe"],
                supplies=["tape"],
            ),
            ob.facility(
                "espresso",
                "espresso machine",
                at="galley",
                guards=["rafe"],
                operations=["brew"],
                products=["cappuccino"],
            ),
        ],
        everyone_owns=["file"],
        home="stores",
    )


lamp_works = ob.parsed(raw_lamp_works)
