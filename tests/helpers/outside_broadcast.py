"""A small outside-broadcast unit for the reader's tests of blind rounds 20-22's classes (no
blind round's office or sentences were read): belongings with a multi-word synonym ("camera
headset", "ear defenders"), a signable form and a signable log sheet, a shared file, a tag
printer that makes rush tags (a product), a dispatch desk that sends things out to places
outside ("courier", "dispatch"), and people with accented names (Renée, Chloë) and
names that are also words (Sandy, Dawn)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("quill", "Quill Amadi", "camera_headset", "call_sheet", "tape"),
    ob.person("renee", "Renée Falk", "camera_headset", "curling_tongs", "call_sheet"),
    ob.person("dov", "Dov Harrow", "camera_headset", "log_sheet", "tape", "battery"),
    ob.person("chloe", "Chloë Varga", "curling_tongs", "log_sheet"),
    ob.person("anouk", "Anouk Teller", "ear_defenders", "call_sheet", "tape"),
    ob.person("piet", "Piet Lund", "log_sheet"),
    ob.person("sandy", "Sandy Okoro", "call_sheet", "tape"),
    ob.person("dawn", "Dawn Pryce", "log_sheet"),
)


def raw_outside_broadcast() -> dict[str, Any]:
    return ob.office_file(
        "outside_broadcast",
        _PEOPLE,
        everyone_owns=["rundown"],
        rooms=[
            ob.room("gear_room", "Gear room", 4.0, 20.0),
            ob.room("dispatch_room", "Dispatch room", 16.0, 20.0),
        ],
        item_types=[
            ob.item("camera_headset", "headset", synonyms=["camera headset", "cans"]),
            ob.item("battery", "spare battery"),
            ob.item("ear_defenders", "ear defenders", mass=True),
            ob.item("curling_tongs", "curling tongs", mass=True),
            ob.item("tape", "tape", "personal", synonyms=["master tape", "sample"]),
            ob.item("call_sheet", "call sheet", "personal", signable=True),
            ob.item("log_sheet", "log sheet", "personal", signable=True),
            ob.item("rundown", "rundown", "electronic", synonyms=["running order"]),
            ob.item("rush_tag", "rush tag", "product"),
        ],
        operations=[
            ob.operation("tag", "tag", name="print rush tags", product="rush_tag"),
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                input="tape",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            ob.facility(
                "tag_printer", "tag printer", at="gear_room", guards=["piet"], operations=["tag"]
            ),
            ob.facility(
                "dispatch_desk",
                "dispatch desk",
                at="dispatch_room",
                guards=["anouk"],
                operations=["courier"],
            ),
        ],
        home="gear_room",
        group=("crew", "Crew"),
    )


outside_broadcast = ob.parsed(raw_outside_broadcast)
