"""A small guesthouse back office for the tests of blind round 14's classes (the round's own
office and sentences were never read). A card encoder makes ordinary door cards from nothing
(no master or all-access variant declared); a tea urn makes tea; a shredder destroys papers
(an operation that consumes its item); a laminator treats a poster (it comes back changed);
ordinary belongings (a step stool, a hole punch) and personal papers (a ledger, a poster)."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import facility, item, office_file, operation, parsed, person, room

_PEOPLE = (
    person("wren", "Wren Okafor", "step_stool", "ledger", "poster"),
    person("basil", "Basil Moreau", "hole_punch", "ledger"),
    person("ottilie", "Ottilie Brandt", "step_stool", "poster"),
    person("cosmo", "Cosmo Delacroix", "ledger"),
    person("juniper", "Juniper Hale", "hole_punch", "poster"),
)


def raw_guesthouse() -> dict[str, Any]:
    return office_file(
        "guesthouse",
        _PEOPLE,
        rooms=[room("back_room", "Back room", 4.0, 20.5), room("pantry", "Pantry", 20.0, 20.5)],
        item_types=[
            item("step_stool", "step stool", synonyms=["kick stool"]),
            item("hole_punch", "hole punch"),
            item("ledger", "ledger", "personal", synonyms=["day book"]),
            item("poster", "poster", "personal"),
            item("door_card", "door card", "product", synonyms=["key card", "room card"]),
            item("tea", "tea", "product", mass=True),
        ],
        operations=[
            operation("encode", "encode", "cut", product="door_card"),
            operation("brew", "brew", product="tea"),
            operation("shred", "shred", input="ledger", consumes=True),
            operation("laminate", "laminate", input="poster"),
        ],
        facilities=[
            facility(
                "encoder",
                "card encoder",
                at="back_room",
                guards=["basil"],
                operations=["encode"],
                products=["door_card"],
            ),
            facility(
                "urn",
                "tea urn",
                at="pantry",
                guards=["cosmo"],
                operations=["brew"],
                products=["tea"],
            ),
            facility(
                "shredder", "shredder", at="back_room", guards=["basil"], operations=["shred"]
            ),
            facility(
                "laminator",
                "laminator",
                at="pantry",
                guards=["cosmo", "juniper"],
                operations=["laminate"],
            ),
        ],
        home="back_room",
    )


guesthouse = parsed(raw_guesthouse)
