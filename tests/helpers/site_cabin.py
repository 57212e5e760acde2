"""A building site's cabin for the reader's tests of round 103's classes (their own offices and
sentences were never read): a laser level Bjorn owns (said "laser" or "level" too), pens and
staplers colleagues have, paper and tape kept in the cabin's cupboard for anyone, and a popcorn
machine that makes popcorn (a facility whose name holds its product's)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("bjorn", "Bjorn Halvorsen", "laser_level", "pen", aliases=["Bjorn"]),
    ob.person("tamsin", "Tamsin Reeve", "pen", "stapler", aliases=["Tamsin"]),
    ob.person("kofi", "Kofi Mensah", "stapler", "tape_measure", aliases=["Kofi"]),
    ob.person("ines", "Ines Duarte", "tape_measure", aliases=["Ines"]),
)


def raw_site_cabin() -> dict[str, Any]:
    return ob.office_file(
        "site cabin",
        _PEOPLE,
        rooms=[
            ob.room("store", "Store", 4.0, 20.0),
            ob.room("mess", "Mess room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("laser_level", "laser level", synonyms=["laser", "level", "line laser"]),
            ob.item("tape_measure", "tape measure", synonyms=["measuring tape"]),
            ob.item("pen", "pen", synonyms=["biro"]),
            ob.item("stapler", "stapler"),
            ob.item("paper", "paper", consumable=True, synonyms=["sheets of paper"]),
            ob.item("tape", "roll of tape", consumable=True, synonyms=["tape", "duct tape"]),
            ob.item("popcorn", "popcorn", "product"),
        ],
        operations=[
            ob.operation("pop", "make", "pop", name="make popcorn", product="popcorn"),
        ],
        facilities=[
            ob.facility(
                "cupboard",
                "cabin cupboard",
                at="store",
                guards=["kofi"],
                supplies=["paper", "tape"],
            ),
            ob.facility(
                "popcorn_machine",
                "popcorn machine",
                at="mess",
                guards=["ines"],
                operations=["pop"],
                products=["popcorn"],
                synonyms=["popper"],
            ),
        ],
        everyone_owns=["file"],
        home="store",
    )


site_cabin = ob.parsed(raw_site_cabin)
