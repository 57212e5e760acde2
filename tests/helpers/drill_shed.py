"""A small joinery shed for the reader's tests of names and what a word refers to (blind rounds
34-36, written from analogues only): colleagues called by a nickname or rank the office declares
("the Gaffer", "Chief"), colleagues whose given names are also English words (Miles, Brook), a
drill and a headset several people own, and everyone's forms and letters."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nell", "Nell Ashby", "headset", "tape", aliases=["Sister Ashby"]),
    ob.person("miles", "Miles Dorran", "drill", "headset", "tape"),
    ob.person("brook", "Brook Hale", "tape", "drill"),
    ob.person("otis", "Otis Crane", "headset", aliases=["Gaffer"]),
    ob.person("rhea", "Rhea Quill", "headset", aliases=["the Chief"]),
    ob.person("sunny", "Sunny Vale", "clipboard"),
    ob.person("guy", "Guy Lowe", "lunchbox"),
    ob.person("dale", "Dale Frost", aliases=["Major"]),
)


def raw_drill_shed() -> dict[str, Any]:
    return ob.office_file(
        "drill shed",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Store room", 4.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("drill", "drill"),
            ob.item("headset", "headset"),
            ob.item("tape", "tape measure"),
            ob.item("clipboard", "clipboard"),
            ob.item("lunchbox", "lunch box", synonyms=["lunch"]),
            ob.item("form", "form", "personal", signable=True),
            ob.item("letter", "referral letter", "personal", signable=True),
            ob.item("certificate", "certificate", "personal"),
        ],
        operations=[],
        facilities=[],
        everyone_owns=["file", "form", "letter", "certificate"],
        home="stores",
    )


drill_shed = ob.parsed(raw_drill_shed)
