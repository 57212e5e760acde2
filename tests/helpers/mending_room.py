"""A book-mending room for the reader's tests of blind round 63's class of work asked of the
people who do it ("Can the binders mend my book?"; the round's own office and sentences were
never read): a mending operation done at a bench whose guards are binders, a printer, and a
colleague (Lee) who could be asked by name."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("rosa", "Rosa Quint", "book", "mug"),
    ob.person("lee", "Lee Hart", "book", aliases=["Lee"]),
    ob.person("ivo", "Ivo Brandt", "book"),
    ob.person("nell", "Nell Oduya"),
    ob.person("omar", "Omar Vance"),
)


def raw_mending_room() -> dict[str, Any]:
    return ob.office_file(
        "mending room",
        _PEOPLE,
        rooms=[
            ob.room("bindery", "Bindery", 4.0, 20.0),
            ob.room("print_room", "Print room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic"),
            ob.item("book", "book"),
            ob.item("mug", "mug"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("mend", "mend", "repair", "fix", input="book"),
            ob.operation("print", "print", input="file", product="printout"),
        ],
        facilities=[
            ob.facility(
                "mending_bench",
                "mending bench",
                at="bindery",
                guards=["nell", "omar"],
                operations=["mend"],
            ),
            ob.facility(
                "printer", "printer", at="print_room", guards=["ivo"], operations=["print"]
            ),
        ],
        everyone_owns=["file"],
        home="print_room",
    )


mending_room = ob.parsed(raw_mending_room)
