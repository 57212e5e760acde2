"""A materials cupboard whose supplies are named in the plural, several of them in more than
one word ("scalpel blades", "cable ties", "AA batteries", "sticky notes", "craft knives",
"storage boxes"), for the reader's tests of a supply asked for in the singular
(reading/measured_items.py): some of those names hold another thing's name whole (a scalpel
and a palette knife colleagues own, a power bank called a "battery"); a cable is no supply of
it. No sentence or name of a measured office is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_SUPPLIES = (
    "scalpel_blades",
    "cable_ties",
    "aa_batteries",
    "sticky_notes",
    "craft_knives",
    "storage_boxes",
)


def raw_supply_cupboard() -> dict[str, Any]:
    people = (
        ob.person("rhea", "Rhea Soto", "mug", "scalpel"),
        ob.person("bram", "Bram Velde", "mug", "power_bank", "knife"),
        ob.person("ivo", "Ivo Renn", "mug"),
    )
    return ob.office_file(
        "supply cupboard",
        people,
        rooms=[ob.room("stores", "Stores", 4.0, 20.0)],
        item_types=[
            ob.item("scalpel_blades", "scalpel blades", consumable=True),
            ob.item("cable_ties", "cable ties", synonyms=["zip ties"], consumable=True),
            ob.item("aa_batteries", "AA batteries", consumable=True),
            ob.item("sticky_notes", "sticky notes", consumable=True),
            ob.item("craft_knives", "craft knives", consumable=True),
            ob.item("storage_boxes", "storage boxes", consumable=True),
            ob.item("mug", "mug"),
            ob.item("scalpel", "scalpel"),
            ob.item("power_bank", "power bank", synonyms=["battery pack", "battery"]),
            ob.item("knife", "palette knife", synonyms=["knife"]),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "cupboard",
                "materials cupboard",
                at="stores",
                guards=["ivo"],
                supplies=_SUPPLIES,
                synonyms=["stores", "cupboard"],
            )
        ],
        home="stores",
    )


supply_cupboard = ob.parsed(raw_supply_cupboard)
