"""A rooftop studio for the reader's tests of blind round 40's statement classes (the round's
own offices and sentences were never read): colleagues whose names are also English words
(Misty and Sunny, weather words; Basil and Holly, a herb and a plant; Gosh, an exclamation),
a pen cupboard that keeps pens, and mugs and staplers several people own."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("rosa", "Rosa Lind", "mug", "stapler"),
    ob.person("basil", "Basil Grant", "stapler", "mug"),
    ob.person("misty", "Misty Okafor", "mug"),
    ob.person("holly", "Holly Marsh", "stapler", "pen"),
    ob.person("gosh", "Gosh Tamang", "mug", "stapler"),
    ob.person("ode", "Femi Ode", "mug"),
)


def raw_roof_garden() -> dict[str, Any]:
    return ob.office_file(
        "roof garden studio",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Store room", 4.0, 20.0),
            ob.room("roof", "Roof", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("mug", "mug"),
            ob.item("stapler", "stapler"),
            ob.item("pen", "pen", consumable=True, synonyms=["pens"]),
            ob.item("form", "form", "personal", signable=True),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "pen_cupboard", "pen cupboard", at="stores", guards=["holly"], supplies=["pen"]
            ),
        ],
        everyone_owns=["file", "form"],
        home="stores",
    )


roof_garden = ob.parsed(raw_roof_garden)
