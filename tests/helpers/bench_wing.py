"""A lab wing for the reader's tests of round 59's classes (fixer fix59b; the round's own
offices and sentences were never read): facilities named for what they make ("Milli-Q unit"
makes deionised water, the dewar liquid nitrogen, the urn hot water) where the containers
people ask for them in (wash bottle, flask, jug) are no item of the office, beside a cup that
is one; a facility that makes nothing (the fume hood); a tool store that keeps several
supplies; things several colleagues own one of (books, staplers), and one (scissors) the
store keeps as well."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob


def raw_wing() -> dict[str, Any]:
    people = (
        ob.person("ines", "Ines Marlow", "book", "stapler", "cup"),
        ob.person("olek", "Olek Brandt", "book", "stapler", "scissors"),
        ob.person("tamsin", "Tamsin Reed", "book", "scissors", "cup"),
        ob.person("rafe", "Rafe Okoro", "notebook"),
    )
    return ob.office_file(
        "bench wing",
        people,
        rooms=[
            ob.room("wash_bay", "Wash bay", 4.0, 20.0),
            ob.room("cryo_room", "Cryo room", 10.0, 20.0),
            ob.room("tea_point", "Tea point", 16.0, 20.0),
            ob.room("stores_room", "Stores room", 22.0, 20.0),
            ob.room("hood_room", "Hood room", 28.0, 20.0),
        ],
        item_types=[
            ob.item("book", "book"),
            ob.item("stapler", "stapler"),
            ob.item("scissors", "scissors"),
            ob.item("notebook", "notebook"),
            ob.item("cup", "cup", synonyms=["mug"]),
            ob.item("drill", "drill"),
            ob.item("tape", "tape", consumable=True),
            ob.item("sandpaper", "sandpaper", consumable=True, mass=True),
            ob.item("ear_defenders", "ear defenders"),
            ob.item("di_water", "deionised water", "product", synonyms=["di water"]),
            ob.item("ln2", "liquid nitrogen", "product", synonyms=["ln2"]),
            ob.item("hot_water", "hot water", "product"),
            ob.item("filter_coffee", "filter coffee", "product"),
        ],
        operations=[
            ob.operation("purify", "purify", name="dispense deionised water", product="di_water"),
            ob.operation("decant", "decant", name="decant liquid nitrogen", product="ln2"),
            ob.operation("boil", "boil", name="boil water", product="hot_water"),
            ob.operation("filter", "filter", name="make filter coffee", product="filter_coffee"),
            ob.operation("extract", "extract", name="extract fumes"),
        ],
        facilities=[
            ob.facility(
                "milliq",
                "Milli-Q unit",
                synonyms=["milli-q", "milliq"],
                at="wash_bay",
                guards=["ines"],
                operations=["purify"],
                products=["di_water"],
            ),
            ob.facility(
                "dewar",
                "dewar",
                at="cryo_room",
                guards=["olek"],
                operations=["decant"],
                products=["ln2"],
            ),
            ob.facility(
                "urn",
                "urn",
                synonyms=["water urn"],
                at="tea_point",
                guards=["tamsin"],
                operations=["boil"],
                products=["hot_water"],
            ),
            ob.facility(
                "filter_machine",
                "filter machine",
                at="tea_point",
                guards=["tamsin"],
                operations=["filter"],
                products=["filter_coffee"],
            ),
            ob.facility(
                "tool_store",
                "tool store",
                synonyms=["stores", "store", "kit room"],
                at="stores_room",
                guards=["rafe"],
                supplies=["drill", "tape", "sandpaper", "ear_defenders", "scissors"],
            ),
            ob.facility(
                "fume_hood",
                "fume hood",
                synonyms=["hood"],
                at="hood_room",
                guards=["rafe"],
                operations=["extract"],
            ),
        ],
        home="stores_room",
    )


wing = ob.parsed(raw_wing)
