"""A riding stables for the reader's tests of blind rounds 23-24: an electronic file known as
"notes" and "briefing pack" (so "vet notes", "ride briefing" are compounds the office does not
list), a farrier's room whose people are named like no other office's, ordinary belongings (a
hoof pick, a stopwatch), a tack-wash room whose machine washes saddle cloths, and a desk of
signable forms."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "hoof_pick", "saddle_cloth", "form"),
    ob.person("tobiah", "Tobiah Crane", "stopwatch", "form"),
    ob.person("maren", "Maren Holt", "hoof_pick", "stopwatch", "form"),
    ob.person("ulla", "Ulla Brisk", "saddle_cloth", "form"),
    ob.person("cosmo", "Cosmo Reyes", "form", aliases=["the vet"]),
)


def raw_stables() -> dict[str, Any]:
    return ob.office_file(
        "stables",
        _PEOPLE,
        everyone_owns=["session_file"],
        desks=ob.desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        desk_word="stall",
        rooms=[
            ob.room("yard_office", "Yard office", 4.0, 18.0),
            ob.room("wash_room", "Wash room", 16.0, 18.0),
            ob.room("vet_room", "Vet room", 10.0, 18.0),
        ],
        item_types=[
            ob.item("hoof_pick", "hoof pick"),
            ob.item("stopwatch", "stopwatch"),
            ob.item("saddle_cloth", "saddle cloth", synonyms=["numnah"]),
            ob.item("form", "form", "personal", signable=True, synonyms=["release form"]),
            ob.item(
                "session_file",
                "session notes",
                "electronic",
                synonyms=["briefing pack", "yard file"],
            ),
        ],
        operations=[
            ob.operation("wash", "wash", "launder", input="saddle_cloth"),
        ],
        facilities=[
            ob.facility(
                "washer", "washing machine", at="wash_room", guards=["ulla"], operations=["wash"]
            ),
        ],
        home="yard_office",
        group=("yard", "Yard"),
    )


stables = ob.parsed(raw_stables)
