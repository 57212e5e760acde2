"""A small testing lab for the reader's tests of blind round 55's classes (the round's own office
and sentences were never read): thermometers and tape measures several people own (one
kept at a cabinet, not with its owner), lunches several people keep in one staff fridge,
gloves a store cupboard keeps for anyone, a shredder that takes a document, and a person
who works in the lab room rather than at a desk."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_FRIDGE_LUNCH = ob.kept("lunch", at="staff_room", facility="staff_fridge")

_PEOPLE = (
    ob.person("kofi", "Kofi Mensah", "thermometer", "tape_measure", _FRIDGE_LUNCH, at="lab"),
    ob.person("rhea", "Rhea Olsen", "thermometer", "tape_measure", _FRIDGE_LUNCH, aliases=["Rhea"]),
    ob.person(
        "sami",
        "Sami Haddad",
        ob.kept("thermometer", at="lab", facility="lab_cabinet"),
        _FRIDGE_LUNCH,
        aliases=["Sami"],
    ),
    ob.person("dana", "Dana Pruitt", "scissors", "ruler", aliases=["Dana"]),
    ob.person("olu", "Olu Bakare", "ruler", "scissors", aliases=["Olu"]),
    ob.person("wren", "Wren Tate", "tape_measure"),
    ob.person("nell", "Nell Amadi", _FRIDGE_LUNCH, at="station"),
)


def raw_sample_lab() -> dict[str, Any]:
    return ob.office_file(
        "sample lab",
        _PEOPLE,
        rooms=[
            ob.room("lab", "Lab", 4.0, 20.0),
            ob.room("staff_room", "Staff room", 20.0, 20.0),
            ob.room("store", "Store room", 12.0, 20.0),
            ob.room("station", "Nurses' station", 28.0, 20.0),
        ],
        item_types=[
            ob.item("document", "document", "personal", signable=True, synonyms=["paper"]),
            ob.item("thermometer", "thermometer"),
            ob.item("tape_measure", "tape measure"),
            ob.item("lunch", "lunch"),
            ob.item("ruler", "ruler"),
            ob.item("scissors", "pair of scissors", synonyms=["scissors"]),
            ob.item("gloves", "exam gloves", consumable=True, synonyms=["gloves"]),
        ],
        operations=[
            ob.operation("shred", "shred", input="document", consumes=True),
        ],
        facilities=[
            ob.facility(
                "staff_fridge",
                "staff fridge",
                at="staff_room",
                guards=["wren"],
                synonyms=["fridge"],
            ),
            ob.facility("lab_cabinet", "lab cabinet", at="lab", guards=["kofi"]),
            ob.facility(
                "store_cupboard", "store cupboard", at="store", guards=["wren"], supplies=["gloves"]
            ),
            ob.facility("shredder", "shredder", at="store", guards=["wren"], operations=["shred"]),
        ],
        everyone_owns=["document"],
        home="store",
    )


sample_lab = ob.parsed(raw_sample_lab)
