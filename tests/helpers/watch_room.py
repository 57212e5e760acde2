"""A fire station's watch room for the reader's tests of blind rounds 25 to 27 (the rounds'
own offices and sentences were never read): people called by rank and surname ("Station
Officer Delaney"), a rank two people hold ("Crew Manager"), initials as an alias ("SO
Delaney"), a hose tester that tests a hose and gives it back, and a bench that services
breathing-apparatus sets (a verb with a soft "c", typed as said)."""

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
    ob.person("hazel", "Hazel Quinn", "hose", "timesheet", aliases=["Watch Manager Quinn"]),
    ob.person("rob", "Rob Stone", "ba_set", aliases=["Crew Manager Stone"]),
    ob.person("ana", "Ana Silva", aliases=["Crew Manager Silva", "CM Silva"]),
    ob.person("kemal", "Kemal Aydin", "hose", "ba_set", "timesheet"),
)


def raw_watch_room() -> dict[str, Any]:
    return ob.office_file(
        "watch room",
        _PEOPLE,
        rooms=[ob.room("appliance_bay", "Appliance bay", 4.0, 20.0)],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["spreadsheet"]),
            ob.item("hose", "hose", synonyms=["length of hose"]),
            ob.item("ba_set", "BA set", synonyms=["breathing set"]),
            ob.item("timesheet", "timesheet", "personal", signable=True, synonyms=["sheet"]),
        ],
        operations=[
            ob.operation("test", "test", "pressure test", input="hose"),
            ob.operation("service", "service", "overhaul", input="ba_set"),
        ],
        facilities=[
            ob.facility(
                "hose_tester",
                "hose tester",
                at="appliance_bay",
                guards=["kemal"],
                operations=["test"],
            ),
            ob.facility(
                "ba_bench", "BA bench", at="appliance_bay", guards=["kemal"], operations=["service"]
            ),
        ],
        everyone_owns=["file"],
        home="appliance_bay",
    )


watch_room = ob.parsed(raw_watch_room)
