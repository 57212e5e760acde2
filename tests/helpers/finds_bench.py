"""A small finds-washing bench where one thing's plural name is another's singular ("scales"
names the weighing scales, "scale" the photo scale), a colleague's small finds are also called
"nails" and "coins", and the office's spreadsheet is also called "the finds register", for the
reader's tests of names, a purpose's object and a record's want (lexicon.py, screen/rewrites.py
purposes, thing_wants.py). No sentence or name of a measured office is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("hana", "Hana Kral", "weighing_scales", "photo_scale", aliases=["Hana"]),
    ob.person("uwe", "Uwe Lind", "small_find", aliases=["Uwe"]),
    ob.person("cleo", "Cleo Park", "small_find", aliases=["Cleo"]),
    ob.person("bo", "Bo Tran", aliases=["Bo"]),
)


def raw_finds_bench() -> dict[str, Any]:
    return ob.office_file(
        "finds bench",
        _PEOPLE,
        rooms=[
            ob.room("wash_room", "Wash room", 4.0, 20.0),
            ob.room("office", "Office", 12.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["finds register", "spreadsheet"]),
            ob.item("photo_scale", "photo scale", synonyms=["scale bar", "scale"]),
            {
                **ob.item("weighing_scales", "weighing scales", synonyms=["scales", "balance"]),
                "purposes": ["weigh"],
            },
            ob.item("finds_bag", "finds bag", consumable=True),
            ob.item("small_find", "small find", "personal", synonyms=["nail", "coin"]),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "stores",
                "stores cupboard",
                at="wash_room",
                guards=["bo"],
                supplies=["finds_bag"],
            )
        ],
        everyone_owns=["file"],
        home="office",
    )


finds_bench = ob.parsed(raw_finds_bench)
