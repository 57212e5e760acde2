"""A small bike workshop where one mechanic owns several tools, only one of which has "tool" in
a name ("bike tool": the multitool), for the reader's tests of one of a colleague's things
named by a word for a kind (reading/screen/one_of_several.py). No sentence or name of a
measured office is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("kofi", "Kofi Mensah", "track_pump", "multitool", "tyre_levers", aliases=["Kofi"]),
    ob.person("edda", "Edda Vik", "multitool", aliases=["Edda"]),
    ob.person("ravi", "Ravi Shah", "stapler", "mug", aliases=["Ravi"]),
    ob.person("lin", "Lin Ho", aliases=["Lin"]),
)


def raw_tool_wall() -> dict[str, Any]:
    return ob.office_file(
        "tool wall",
        _PEOPLE,
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.0),
            ob.room("office", "Office", 12.0, 20.0),
        ],
        item_types=[
            ob.item("document", "document", "personal", synonyms=["form", "letter"]),
            ob.item("track_pump", "track pump", synonyms=["floor pump"]),
            ob.item("multitool", "multitool", synonyms=["multi-tool", "bike tool"]),
            ob.item("tyre_levers", "tyre levers"),
            ob.item("stapler", "stapler"),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[],
        everyone_owns=["document"],
        home="office",
    )


tool_wall = ob.parsed(raw_tool_wall)
