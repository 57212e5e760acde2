"""A small book bindery and reading room for the reader's tests of blind round 13's classes
(the round's own office and sentences were never read). Several colleagues' given names are
also English words (Penny, Ivy, Robin, Page), some carry diacritics (Thảo, Łukasz, Zoë, Jürgen);
the bindery rebinds a worn book and prints a flyer from a file; a staff fridge keeps people's
lunches; a kitchen makes coffee and water; condition reports are signed by a colleague."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("penny", "Penny Castellanos", "puppet", "report"),
    ob.person("ivy", "Ivy Marchetti", "kick_stool", aliases=["Ives"]),
    ob.person("robin", "Robin Okonkwo", "report"),
    ob.person("page", "Oksana Page", "kick_stool", "report"),
    ob.person("thao", "Thảo Nguyễn", "report"),
    ob.person("lukasz", "Łukasz Wróbel", "bone_folder", aliases=["Luke"]),
    ob.person("zoe", "Zoë Brandt", "bone_folder", "report"),
    ob.person("jurgen", "Jürgen Falk", ob.kept("lunch", at="kitchen", facility="fridge"), "report"),
)


def raw_bindery() -> dict[str, Any]:
    return ob.office_file(
        "bindery",
        _PEOPLE,
        everyone_owns=["flyer_file", "book"],
        rooms=[
            ob.room("workroom", "Workroom", 4.0, 20.5),
            ob.room("kitchen", "Kitchen", 11.0, 20.5),
        ],
        item_types=[
            ob.item("puppet", "puppet", synonyms=["hand puppet"]),
            ob.item("kick_stool", "kick stool", synonyms=["step stool"]),
            ob.item("bone_folder", "bone folder"),
            ob.item("lunch", "lunch box", synonyms=["lunchbox"]),
            ob.item("report", "condition report", "personal", signable=True),
            ob.item("book", "worn book", synonyms=["damaged book"]),
            ob.item("flyer_file", "flyer file", "electronic"),
            ob.item("brochure", "brochure", "product", synonyms=["flyer"]),
            ob.item("rebound", "rebound book", "product"),
            ob.item("coffee", "coffee", "product"),
            ob.item("water", "water", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="flyer_file", product="brochure"),
            ob.operation("rebind", "rebind", input="book", product="rebound"),
            ob.operation("brew", "brew", name="make coffee", product="coffee"),
            ob.operation("pour", "pour", name="pour water", product="water"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="workroom",
                guards=["page"],
                operations=["print"],
                products=["brochure"],
            ),
            ob.facility(
                "press",
                "bindery press",
                at="workroom",
                guards=["page"],
                operations=["rebind"],
                products=["rebound"],
            ),
            ob.facility(
                "fridge", "staff fridge", at="kitchen", guards=["robin"], synonyms=["fridge"]
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["robin"],
                operations=["brew"],
                products=["coffee"],
            ),
            ob.facility(
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


bindery = ob.parsed(raw_bindery)
