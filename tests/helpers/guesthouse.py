"""A small guesthouse back office for the tests of blind round 14's classes (the round's own
office and sentences were never read). A card encoder makes ordinary door cards from nothing
(no master or all-access variant declared); a tea urn makes tea; a shredder destroys papers
(an operation that consumes its item); a laminator treats a poster (it comes back changed);
ordinary belongings (a step stool, a hole punch) and personal papers (a ledger, a poster)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("wren", "Wren Okafor", "step_stool", "ledger", "poster"),
    ob.person("basil", "Basil Moreau", "hole_punch", "ledger"),
    ob.person("ottilie", "Ottilie Brandt", "step_stool", "poster"),
    ob.person("cosmo", "Cosmo Delacroix", "ledger"),
    ob.person("juniper", "Juniper Hale", "hole_punch", "poster"),
)


def raw_guesthouse() -> dict[str, Any]:
    return ob.office_file(
        "guesthouse",
        _PEOPLE,
        rooms=[
            ob.room("back_room", "Back room", 4.0, 20.5),
            ob.room("pantry", "Pantry", 20.0, 20.5),
        ],
        item_types=[
            ob.item("step_stool", "step stool", synonyms=["kick stool"]),
            ob.item("hole_punch", "hole punch"),
            ob.item("ledger", "ledger", "personal", synonyms=["day book"]),
            ob.item("poster", "poster", "personal"),
            ob.item("door_card", "door card", "product", synonyms=["key card", "room card"]),
            ob.item("tea", "tea", "product", mass=True),
        ],
        operations=[
            ob.operation("encode", "encode", "cut", product="door_card"),
            ob.operation("brew", "brew", product="tea"),
            ob.operation("shred", "shred", input="ledger", consumes=True),
            ob.operation("laminate", "laminate", input="poster"),
        ],
        facilities=[
            ob.facility(
                "encoder",
                "card encoder",
                at="back_room",
                guards=["basil"],
                operations=["encode"],
                products=["door_card"],
            ),
            ob.facility(
                "urn",
                "tea urn",
                at="pantry",
                guards=["cosmo"],
                operations=["brew"],
                products=["tea"],
            ),
            ob.facility(
                "shredder", "shredder", at="back_room", guards=["basil"], operations=["shred"]
            ),
            ob.facility(
                "laminator",
                "laminator",
                at="pantry",
                guards=["cosmo", "juniper"],
                operations=["laminate"],
            ),
        ],
        home="back_room",
    )


guesthouse = ob.parsed(raw_guesthouse)
