"""A falconry mews: each falconer's glove (a "fist"), lures on a shelf, a wash station that
disinfects gloves (and keeps the disinfectant, "virkon") and a prep table that makes the
birds' rations ("chopped quail"). Its birds (Blaze, ...) are nobody of the office: said by
name, they are no colleague to look up."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob


def raw_mews() -> dict[str, Any]:
    people = (
        ob.person("ava", "Ava Reed"),
        ob.person("sam", "Sam Cole"),
        ob.person("noor", "Noor Khan"),
    )
    return ob.office_file(
        "mews",
        people,
        rooms=[
            ob.room("mews_room", "Mews", 4.0, 20.0),
            ob.room("wash_room", "Wash room", 12.0, 20.0),
            ob.room("prep_room", "Prep room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("glove", "glove", "personal", synonyms=["fist"]),
            ob.item("lure", "lure"),
            ob.item("ration", "ration", "product", synonyms=["chopped quail", "day old chicks"]),
            ob.item("disinfectant", "disinfectant", synonyms=["virkon"]),
        ],
        operations=[
            ob.operation("disinfect", "disinfect", "dip", "sanitise", input="glove"),
            ob.operation("food_prep", "prep", "prepare", name="food prep", product="ration"),
        ],
        facilities=[
            ob.facility(
                "lure_shelf", "lure shelf", at="mews_room", guards=["noor"], supplies=["lure"]
            ),
            ob.facility(
                "wash_station",
                "wash station",
                at="wash_room",
                guards=["noor"],
                operations=["disinfect"],
                supplies=["disinfectant"],
            ),
            ob.facility(
                "prep_table",
                "prep table",
                at="prep_room",
                guards=["sam"],
                operations=["food_prep"],
                products=["ration"],
            ),
        ],
        everyone_owns=["glove"],
        home="mews_room",
    )


mews_office = ob.parsed(raw_mews)
