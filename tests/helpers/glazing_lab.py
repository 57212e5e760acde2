"""An optician's glazing lab for the reader's tests of round 189's classes about people outside
the office, exclusions and grumbles (the round's own offices and sentences were never read):
a glazer that glazes what is on a job tray (everyone keeps one, and an order), a spudger kept
for prising, a laptop, colleagues whose names are English words (Miles, Frank, Sandy) and one
whose family name is said with a title (Mr Okoro)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ada", "Ada Lane", aliases=["Ada"]),
    ob.person("miles", "Miles Hart", "spudger", aliases=["Miles"]),
    ob.person("frank", "Frank Dee", "laptop", aliases=["Frank"]),
    ob.person("sandy", "Sandy Reyes", aliases=["Sandy"]),
    ob.person("tunde", "Tunde Okoro", "spudger", aliases=["Tunde"]),
)


def raw_glazing_lab() -> dict[str, Any]:
    return ob.office_file(
        "glazing lab",
        _PEOPLE,
        rooms=[ob.room("lab", "Glazing room", 4.0, 20.0)],
        item_types=[
            ob.item("tray", "job tray", "personal", synonyms=["tray"]),
            ob.item("spudger", "spudger") | {"purposes": ["prise", "pry"]},
            ob.item("pen", "pen"),
            ob.item("order", "order", "personal", synonyms=["job"]),
            ob.item("laptop", "laptop", "personal"),
        ],
        operations=[ob.operation("glaze", "glaze", name="glazing", input="tray")],
        facilities=[
            ob.facility("glazer", "glazer", at="lab", guards=["sandy"], operations=["glaze"]),
        ],
        everyone_owns=["tray", "pen", "order"],
        home="lab",
    )


glazing_lab = ob.parsed(raw_glazing_lab)
