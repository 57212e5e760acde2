"""A stores cupboard for the reader's tests of round 103's classes (fixer fix103b; the
round's own offices and sentences were never read): supplies named by several words
("sticky notes", "hand sanitiser") with synonyms of their own ("post-its", "hand gel",
"alcohol gel"), stuff the office marks as such (``mass``), and supplies whose names begin
with a word that is also a verb ("bin bags", "scrap paper", "cut flowers")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_SUPPLIES = (
    "sticky_notes",
    "sanitiser",
    "bin_bags",
    "scrap_paper",
    "cut_flowers",
    "staples",
    "copier_paper",
    "wipes",
    "paint_roller",
    "lint_roller",
    "ink_pad",
)


def raw_stores() -> dict[str, Any]:
    people = (
        ob.person("ada", "Ada Holm", "mug"),
        ob.person("tomas", "Tomas Reyes", "mug"),
        ob.person("nell", "Nell Ortiz", "mug"),
    )
    return ob.office_file(
        "stores",
        people,
        rooms=[ob.room("stores", "Stores room", 4.0, 20.0)],
        item_types=[
            ob.item(
                "sticky_notes",
                "sticky notes",
                synonyms=["post-its", "post-it notes", "pad of post-its"],
                consumable=True,
            ),
            ob.item(
                "sanitiser",
                "hand sanitiser",
                synonyms=["hand gel", "alcohol gel", "hand rub"],
                consumable=True,
                mass=True,
            ),
            ob.item("bin_bags", "bin bags", synonyms=["rubbish bags"], consumable=True),
            ob.item("scrap_paper", "scrap paper", consumable=True, mass=True),
            ob.item("cut_flowers", "cut flowers"),
            ob.item("staples", "staples", consumable=True),
            ob.item("copier_paper", "copier paper", consumable=True, mass=True),
            ob.item("wipes", "wipes", synonyms=["wet wipes"], consumable=True),
            # two types whose names end in one noun ("roller"); a unit noun heading one
            # type's names ("pad")
            ob.item("paint_roller", "paint roller", synonyms=["decorating roller"]),
            ob.item("lint_roller", "lint roller", synonyms=["fluff roller"]),
            ob.item("ink_pad", "ink pad", synonyms=["stamp pad"]),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "cupboard", "stores cupboard", at="stores", guards=["nell"], supplies=_SUPPLIES
            )
        ],
        home="stores",
    )


stores = ob.parsed(raw_stores)
