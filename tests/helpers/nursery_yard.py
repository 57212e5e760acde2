"""A plant nursery for the reader's tests of blind round 43-44's class F (the round's own offices
and sentences were never read): a potting shed that keeps twine and paper clips for anyone, a
plotter whose product is called by its own word ("plot print", "plot"), a scanner whose product
is a pdf, a kettle that makes tea and coffee, and tools kept for a purpose (a pen to write with,
scissors to cut with)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("soren", "Søren Holm", "pen", aliases=["Søren"]),
    ob.person("ada", "Ada Brook", "scissors", aliases=["Ada"]),
    ob.person("hal", "Hal Moss", aliases=["Hal"]),
    ob.person("min", "Min Park", aliases=["Min"]),
    ob.person("kim", "Kim Vale", "pen", aliases=["Kim"]),
)


def raw_nursery_yard() -> dict[str, Any]:
    return ob.office_file(
        "nursery yard",
        _PEOPLE,
        rooms=[
            ob.room("shed", "Potting shed", 4.0, 20.0),
            ob.room("office_room", "Site office", 20.0, 20.0),
            ob.room("mess", "Mess room", 12.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["drawing"]) | {"purposes": []},
            ob.item("pen", "pen", synonyms=["biro"]) | {"purposes": ["write"]},
            ob.item("scissors", "scissors", synonyms=["snips"]) | {"purposes": ["cut"]},
            ob.item("twine", "twine", consumable=True, synonyms=["garden twine"]),
            ob.item("clips", "paper clips", consumable=True, synonyms=["paper clip"]),
            ob.item("milk", "milk", consumable=True),
            ob.item("plot", "plot print", "product", synonyms=["plot"]),
            ob.item("tea", "tea", "product", synonyms=["cup of tea"]),
            ob.item("coffee", "coffee", "product", synonyms=["latte"]),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="plot"),
            ob.operation("make_tea", "brew", name="make tea", product="tea"),
            ob.operation("make_coffee", "percolate", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "shed_shelves",
                "potting shed shelves",
                at="shed",
                guards=["kim"],
                supplies=["twine", "clips"],
            ),
            ob.facility(
                "plotter", "plotter", at="office_room", guards=["kim"], operations=["print"]
            ),
            ob.facility(
                "kettle",
                "kettle",
                at="mess",
                guards=["min"],
                operations=["make_tea", "make_coffee"],
            ),
            ob.facility("fridge", "fridge", at="mess", guards=["min"], supplies=["milk"]),
        ],
        everyone_owns=["file"],
        home="office_room",
    )


nursery_yard = ob.parsed(raw_nursery_yard)
