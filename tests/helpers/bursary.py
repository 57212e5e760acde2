"""A school bursary and workroom for the reader's tests of blind round 57's classes (the round's
own offices and sentences were never read): a print/copy/scan room, a laminator and a shredder,
a mounting bench, supplies of foil and markers, and colleagues whose names are also words or
end in s (Miles, James)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("gwen", "Gwen Price", "stopwatch", "eraser", "clock", "fan"),
    ob.person("bronwen", "Bronwen Hale", "loupe"),
    ob.person("miles", "Miles Ford", "torch", aliases=["Miles"]),
    ob.person("james", "James Ode", "stapler", aliases=["James"]),
    ob.person("ana", "Ana Lusk", "stapler"),
    ob.person("bursar", "Ruth Bell", aliases=["Bursar", "the Bursar"]),
)


def raw_bursary() -> dict[str, Any]:
    return ob.office_file(
        "bursary",
        _PEOPLE,
        rooms=[
            ob.room("workroom", "Workroom", 4.0, 20.0),
            ob.room("stores", "Stores", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document", "doc"]),
            ob.item("printout", "printout", "product"),
            ob.item("sheet", "laminated sheet", "product"),
            ob.item("photocopy", "photocopy", "product"),
            ob.item("stopwatch", "stopwatch"),
            ob.item("loupe", "loupe", synonyms=["magnifier"]),
            ob.item("torch", "torch", synonyms=["flashlight"]),
            ob.item("stapler", "stapler"),
            ob.item("foil", "foil", consumable=True),
            ob.item("eraser", "whiteboard eraser", synonyms=["board rubber"]),
            ob.item("clock", "desk clock", synonyms=["table clock"]),
            ob.item("fan", "desk fan", synonyms=["table fan"]),
            ob.item(
                "marker",
                "whiteboard marker",
                consumable=True,
                synonyms=["board pen", "marker"],
            ),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("copy", "copy", input="file", product="photocopy"),
            ob.operation("scan", "scan", input="file"),
            ob.operation("laminate", "laminate", input="file", product="sheet"),
            ob.operation("shred", "shred", input="file", consumes=True),
        ],
        facilities=[
            ob.facility(
                "print_room",
                "print room",
                at="workroom",
                guards=["gwen"],
                operations=["print", "copy", "scan"],
            ),
            ob.facility(
                "laminator", "laminator", at="workroom", guards=["gwen"], operations=["laminate"]
            ),
            ob.facility(
                "shredder", "shredder", at="workroom", guards=["gwen"], operations=["shred"]
            ),
            ob.facility(
                "stores", "stores", at="stores", guards=["ana"], supplies=["foil", "marker"]
            ),
        ],
        everyone_owns=["file"],
        home="workroom",
    )


bursary = ob.parsed(raw_bursary)
