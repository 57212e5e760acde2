"""A small book bindery and reading room for the reader's tests of blind round 13's classes
(the round's own office and sentences were never read). Several colleagues' given names are
also English words (Penny, Ivy, Robin, Page), some carry diacritics (Thảo, Łukasz, Zoë, Jürgen);
the bindery rebinds a worn book and prints a flyer from a file; a staff fridge keeps people's
lunches; a kitchen makes coffee and water; condition reports are signed by a colleague."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    facility,
    item,
    kept,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("penny", "Penny Castellanos", "puppet", "report"),
    person("ivy", "Ivy Marchetti", "kick_stool", aliases=["Ives"]),
    person("robin", "Robin Okonkwo", "report"),
    person("page", "Oksana Page", "kick_stool", "report"),
    person("thao", "Thảo Nguyễn", "report"),
    person("lukasz", "Łukasz Wróbel", "bone_folder", aliases=["Luke"]),
    person("zoe", "Zoë Brandt", "bone_folder", "report"),
    person("jurgen", "Jürgen Falk", kept("lunch", at="kitchen", facility="fridge"), "report"),
)


def raw_bindery() -> dict[str, Any]:
    return office_file(
        "bindery",
        _PEOPLE,
        everyone_owns=["flyer_file", "book"],
        rooms=[room("workroom", "Workroom", 4.0, 20.5), room("kitchen", "Kitchen", 11.0, 20.5)],
        item_types=[
            item("puppet", "puppet", synonyms=["hand puppet"]),
            item("kick_stool", "kick stool", synonyms=["step stool"]),
            item("bone_folder", "bone folder"),
            item("lunch", "lunch box", synonyms=["lunchbox"]),
            item("report", "condition report", "personal", signable=True),
            item("book", "worn book", synonyms=["damaged book"]),
            item("flyer_file", "flyer file", "electronic"),
            item("brochure", "brochure", "product", synonyms=["flyer"]),
            item("rebound", "rebound book", "product"),
            item("coffee", "coffee", "product"),
            item("water", "water", "product"),
        ],
        operations=[
            operation("print", "print", input="flyer_file", product="brochure"),
            operation("rebind", "rebind", input="book", product="rebound"),
            operation("brew", "brew", name="make coffee", product="coffee"),
            operation("pour", "pour", name="pour water", product="water"),
        ],
        facilities=[
            facility(
                "printer",
                "printer",
                at="workroom",
                guards=["page"],
                operations=["print"],
                products=["brochure"],
            ),
            facility(
                "press",
                "bindery press",
                at="workroom",
                guards=["page"],
                operations=["rebind"],
                products=["rebound"],
            ),
            facility("fridge", "staff fridge", at="kitchen", guards=["robin"], synonyms=["fridge"]),
            facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["robin"],
                operations=["brew"],
                products=["coffee"],
            ),
            facility(
                "water_cooler",
                "water cooler",
                at="kitchen",
                guards=["robin"],
                operations=["pour"],
                products=["water"],
            ),
        ],
        home="workroom",
    )


bindery = parsed(raw_bindery)
