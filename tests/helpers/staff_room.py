"""A school staff room for the reader's tests of blind round 57-58's classes about whom an item
is for, whose it is and who a name or pronoun points at (the round's own offices and sentences
were never read): a fridge that keeps Ravi's flask, a prep cabinet that keeps Dr N's
goggles, a kettle whose one operation is asked for with "brew" (tea), a coffee machine,
colleagues known by a title and an initial ("Mr K", "Dr N"), word-names (Miles, Ivy), a short
name (Bron for Bronwen) and things several people own (drill, torch, pen, charger)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person(
        "ravi",
        "Ravi Mehta",
        "tripod",
        ob.kept("flask", at="kitchen", facility="fridge"),
        aliases=["Ravi"],
    ),
    ob.person("kofi", "Kofi Kessler", "pen", aliases=["Mr K"]),
    ob.person("noor", "Noor Haddad", "tripod", aliases=["Noor"]),
    ob.person("tam", "Tam Rees", aliases=["Tam"]),
    ob.person("bronwen", "Bronwen Lloyd", "charger", aliases=["Bron"]),
    ob.person("tariq", "Tariq Aziz", "drill", aliases=["Tariq"]),
    ob.person("miles", "Miles Gray", "drill", "torch", aliases=["Miles"]),
    ob.person("ivy", "Ivy Stone", "drill", aliases=["Ivy"]),
    ob.person("omar", "Omar Farouk", "torch", aliases=["Omar"]),
    ob.person("kit", "Kit Marsh", aliases=["Kit"]),
    ob.person(
        "nadia",
        "Nadia Novak",
        ob.kept("goggles", at="store", facility="prep_cabinet"),
        aliases=["Dr N", "Nadia"],
    ),
    ob.person("lee", "Lee Park", "pen", "charger", "stapler", aliases=["Lee"]),
    ob.person("ruth", "Ruth Bell", "charger", "pen", aliases=["Ruth"]),
    ob.person("zhang", "Zhang Min", aliases=["Zhang"]),
    ob.person("ana", "Ana Silva", aliases=["Ana"]),
)


def raw_staff_room() -> dict[str, Any]:
    return ob.office_file(
        "staff room",
        _PEOPLE,
        rooms=[
            ob.room("kitchen", "Kitchen", 4.0, 20.0),
            ob.room("store", "Store room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("tea", "tea", "product"),
            ob.item("coffee", "coffee", "product"),
            ob.item("tripod", "tripod"),
            ob.item("flask", "flask"),
            ob.item("drill", "drill"),
            ob.item("torch", "torch"),
            ob.item("pen", "pen"),
            ob.item("charger", "charger"),
            ob.item("goggles", "goggles"),
            ob.item("stapler", "stapler"),
        ],
        operations=[
            ob.operation("tea", "brew", name="make tea", product="tea"),
            ob.operation("coffee", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "kettle",
                "kettle",
                at="kitchen",
                guards=["tam"],
                operations=["tea"],
                products=["tea"],
            ),
            ob.facility("fridge", "fridge", at="kitchen", guards=["tam"]),
            ob.facility("prep_cabinet", "prep cabinet", at="store", guards=["tam"]),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["tam"],
                operations=["coffee"],
                products=["coffee"],
            ),
        ],
        home="store",
    )


staff_room = ob.parsed(raw_staff_room)
