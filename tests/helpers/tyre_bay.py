"""A tyre and frame workshop for the reader's tests of blind round 28's speech-act classes (the
round's own office and sentences were never read): a ruler and a tray several people own, a
supply room that keeps staples, a laminator, a service whose verb is also a withdrawal word
("scrap" an old tyre), and a colleague whose name is also a colour (Amber)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "ruler", "tray", "tyre"),
    ob.person("bruno", "Bruno Keel", "ruler", "tray", aliases=["Bruno"]),
    ob.person("tove", "Tove Lind", "tray", "tyre"),
    ob.person("amber", "Amber Ruiz", "tyre"),
    ob.person("marlo", "Marlo Pike", "clipboard"),
)


def raw_tyre_bay() -> dict[str, Any]:
    return ob.office_file(
        "tyre bay",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Supply room", 4.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0),
            ob.room("bench_room", "Packing bench", 12.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("ruler", "ruler"),
            ob.item("tray", "tray"),
            ob.item("tyre", "tyre", synonyms=["tire"]),
            ob.item("clipboard", "clipboard"),
            ob.item("form", "form", "personal", signable=True),
            ob.item("staples", "box of staples", consumable=True, synonyms=["staples"]),
            ob.item("sheet", "laminated sheet", "product"),
        ],
        operations=[
            ob.operation("scrap", "scrap", input="tyre", consumes=True),
            ob.operation("laminate", "laminate", input="file", product="sheet"),
        ],
        facilities=[
            ob.facility(
                "supply_room",
                "supply room",
                at="stores",
                guards=["marlo"],
                supplies=["staples"],
            ),
            ob.facility(
                "laminator", "laminator", at="stores", guards=["marlo"], operations=["laminate"]
            ),
            ob.facility(
                "scrap_cage", "scrap cage", at="yard", guards=["tove"], operations=["scrap"]
            ),
        ],
        everyone_owns=["file", "form"],
        home="stores",
    )


tyre_bay = ob.parsed(raw_tyre_bay)
