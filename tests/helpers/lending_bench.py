"""A makers' lending bench for the reader's tests of blind round 59-60's classes about who gets
an item and which item a word names (the round's own offices and sentences were never read):
lamps, clamps, headphones, chargers and a tape measure that several colleagues own (Mira her
own headphones too), a paper bill whose synonym is "invoice" beside an electronic file type
that knows no format word, and two colleagues who share a name: Tilly Grant, and Grant Okoro,
whose given name is her surname."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("mira", "Mira Holt", "lamp", "headphones", "charger", aliases=["Mira"]),
    ob.person("bea", "Bea Soto", "lamp", "headphones", aliases=["Bea"]),
    ob.person("jory", "Jory Quint", "clamp", "tape_measure", "charger", aliases=["Jory"]),
    ob.person("omar", "Omar Reyes", "clamp", aliases=["Omar"]),
    ob.person("tilly", "Tilly Grant", "lamp"),
    ob.person("grant", "Grant Okoro", "drill", "headphones"),
    ob.person("wren", "Wren Adey", "drill", "tape_measure", aliases=["Wren"]),
)


def raw_lending_bench() -> dict[str, Any]:
    return ob.office_file(
        "lending bench",
        _PEOPLE,
        rooms=[
            ob.room("store", "Store room", 4.0, 20.0),
            ob.room("print_bay", "Print bay", 20.0, 20.0),
        ],
        item_types=[
            ob.item("lamp", "lamp"),
            ob.item("clamp", "clamp"),
            ob.item("drill", "drill"),
            ob.item("headphones", "headphones", synonyms=["earphones", "earbuds"]),
            ob.item("charger", "charger"),
            ob.item("tape_measure", "tape measure"),
            ob.item("bill", "bill", "personal", synonyms=["invoice", "receipt"]),
            ob.item("file", "digital file", "electronic", synonyms=["file"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[ob.operation("print", "print", input="file", product="printout")],
        facilities=[
            ob.facility("printer", "printer", at="print_bay", guards=[], operations=["print"]),
        ],
        everyone_owns=["bill", "file"],
        home="store",
    )


lending_bench = ob.parsed(raw_lending_bench)


def raw_paper_bench() -> dict[str, Any]:
    """The same bench with no electronic file type: its bills are paper only."""
    raw = raw_lending_bench()
    raw["item_types"] = [t for t in raw["item_types"] if t.get("kind") != "electronic"]
    raw["operations"] = []
    raw["facilities"] = []
    raw["item_types"] = [t for t in raw["item_types"] if t["id"] != "printout"]
    for p in raw["people"]:
        p["owns"] = [o for o in p["owns"] if o["type"] != "file"]
    return raw


paper_bench = ob.parsed(raw_paper_bench)
