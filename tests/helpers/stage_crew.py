"""A theatre's stage crew for the reader's tests of blind round 67's classes (the round's own
office and sentences were never read): headsets, chargers, mugs and books several people own,
costumes, a washer that washes them, a microwave that heats a lunch, a dishwasher that washes
a mug, and a colleague whose name carries a diaeresis (Zoë)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("zoe", "Zoë Marsh", "headset", "costume", "mug", "book", aliases=["Zoë", "Zoe"]),
    ob.person("ana", "Ana Ruiz", "headset", "charger", "lunch", "book", aliases=["Ana"]),
    ob.person("sam", "Sam Okoro", "charger", "mug", "stapler", "book", aliases=["Sam"]),
    ob.person("kit", "Kit Lowe", "headset", "costume", "charger", "mug", "lunch", aliases=["Kit"]),
    ob.person("remy", "Remy Vance", "pen", aliases=["Remy"]),
)


def raw_stage_crew() -> dict[str, Any]:
    return ob.office_file(
        "stage crew",
        _PEOPLE,
        rooms=[
            ob.room("wardrobe", "Wardrobe", 4.0, 20.0),
            ob.room("green_room", "Green room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("headset", "headset"),
            ob.item("charger", "charger"),
            ob.item("costume", "costume"),
            ob.item("mug", "mug"),
            ob.item("lunch", "lunch"),
            ob.item("stapler", "stapler"),
            ob.item("book", "book"),
            ob.item("pen", "pen"),
        ],
        operations=[
            ob.operation("wash", "wash", input="costume"),
            ob.operation("heat", "heat", "warm", input="lunch"),
            ob.operation("dishwash", "dishwash", name="run through the dishwasher", input="mug"),
        ],
        facilities=[
            ob.facility("washer", "washer", at="wardrobe", guards=["kit"], operations=["wash"]),
            ob.facility(
                "microwave", "microwave", at="green_room", guards=["sam"], operations=["heat"]
            ),
            ob.facility(
                "dishwasher", "dishwasher", at="green_room", guards=["sam"], operations=["dishwash"]
            ),
        ],
        home="green_room",
    )


stage_crew = ob.parsed(raw_stage_crew)
