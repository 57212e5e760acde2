"""A small print and admin room for the reader's tests of blind rounds 43-48's classes (the
rounds' own offices and sentences were never read): colleagues whose given names are also
ordinary English words (Frank, Bill, Grant, Noble, Rich), a laminator that laminates a badge,
a shredder for drafts, and each person's electronic file."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("frank", "Frank Osei", "badge", "stapler", "mug", "draft", aliases=["Frank"]),
    ob.person("bill", "Bill Hart", "badge", "mug", aliases=["Bill"]),
    ob.person("grant", "Grant Ng", "badge", "stapler", aliases=["Grant"]),
    ob.person("noble", "Noble Addo", "badge", "mug", aliases=["Noble"]),
    ob.person("rich", "Rich Tan", "badge", "draft", aliases=["Rich"]),
    ob.person("petra", "Petra Vlk", "badge", "mug", "draft"),
)


def raw_word_names() -> dict[str, Any]:
    return ob.office_file(
        "word names",
        _PEOPLE,
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.0),
            ob.room("meeting", "Meeting room", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("badge", "badge", "personal", synonyms=["ID card", "crew ID"]),
            ob.item("stapler", "stapler"),
            ob.item("mug", "mug", synonyms=["cup"]),
            ob.item("draft", "draft", "personal"),
            ob.item("form", "form", "personal", signable=True),
            ob.item("sheet", "laminated badge", "product"),
        ],
        operations=[
            ob.operation("laminate", "laminate", input="badge", product="sheet"),
            ob.operation("shred", "shred", input="draft", consumes=True),
        ],
        facilities=[
            ob.facility(
                "laminator", "laminator", at="print_room", guards=["petra"], operations=["laminate"]
            ),
            ob.facility(
                "shredder", "shredder", at="print_room", guards=["petra"], operations=["shred"]
            ),
        ],
        everyone_owns=["file", "form"],
        home="print_room",
    )


word_names = ob.parsed(raw_word_names)
