"""A fire station's watch room for the reader's tests of blind rounds 25 to 27 (the rounds'
own offices and sentences were never read): people called by rank and surname ("Station
Officer Delaney"), a rank two people hold ("Watch Manager"), initials as an alias ("SO
Delaney"), and a hose tester that tests a hose and gives it back."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person(
        "frank",
        "Frank Delaney",
        "hose",
        aliases=["Frank", "Station Officer Delaney", "SO Delaney"],
    ),
    ob.person("hazel", "Hazel Quinn", "hose", aliases=["Watch Manager Quinn"]),
    ob.person("rob", "Rob Stone", aliases=["Watch Manager Stone"]),
    ob.person("kemal", "Kemal Aydin", "hose"),
)


def raw_watch_room() -> dict[str, Any]:
    return ob.office_file(
        "watch room",
        _PEOPLE,
        rooms=[ob.room("appliance_bay", "Appliance bay", 4.0, 20.0)],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["spreadsheet"]),
            ob.item("hose", "hose", synonyms=["length of hose"]),
        ],
        operations=[ob.operation("test", "test", "pressure test", input="hose")],
        facilities=[
            ob.facility(
                "hose_tester",
                "hose tester",
                at="appliance_bay",
                guards=["kemal"],
                operations=["test"],
            )
        ],
        everyone_owns=["file"],
        home="appliance_bay",
    )


watch_room = ob.parsed(raw_watch_room)
