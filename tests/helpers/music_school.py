"""A music school's office, for the reader's tests of services on one's own thing and of
operations whose names carry an object (issue 23, fixer 151a).

- Frank (whose given name is also a word) keeps the instrument store, which rehairs bows and
  keeps rosin for anyone; Nell keeps the repair bench, whose operations are named with an
  object of their own ("restring a guitar", "polish a trumpet"); Ada keeps the recording
  studio (a room with a facility of the same name, where lessons are recorded) and the
  stationery cupboard, which keeps glue and folders' labels for anyone.
- Several people own bows, guitars, trumpets, clip-on tuners and music folders.
"""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("frank", "Frank Osei", "bow", "tuner"),
    ob.person("nell", "Nell Varga", "guitar", "tuner"),
    ob.person("ada", "Ada Brennan", "trumpet", "folder"),
    ob.person("tom", "Tom Reyes", "bow", "guitar", "tuner", "folder"),
    ob.person("ines", "Ines Kowal", "bow", "trumpet", "tuner"),
    ob.person("omar", "Omar Haddad", "guitar", "folder", "tuner"),
)


def raw_music_school() -> dict[str, Any]:
    return ob.office_file(
        "music_school",
        _PEOPLE,
        rooms=[
            ob.room("store_room", "Store room", 6.0, 18.0),
            ob.room("workshop", "Workshop", 14.0, 18.0),
            ob.room("studio", "Recording studio", 22.0, 18.0),
            ob.room("office", "Office", 30.0, 18.0),
        ],
        item_types=[
            ob.item("bow", "bow", synonyms=["violin bow"]),
            ob.item("guitar", "guitar"),
            ob.item("trumpet", "trumpet"),
            ob.item("tuner", "clip-on tuner", synonyms=["tuner"]),
            ob.item("folder", "music folder", synonyms=["folder"]),
            ob.item("rosin", "rosin", consumable=True, mass=True),
            ob.item("glue", "glue", consumable=True, mass=True),
            ob.item("recording", "recording", "product"),
        ],
        operations=[
            ob.operation("rehair", "rehair", name="rehair", input="bow"),
            ob.operation("restring", "restring", name="restring a guitar", input="guitar"),
            ob.operation("polish", "polish", "shine", name="polish a trumpet", input="trumpet"),
            ob.operation("record", "record", name="record", product="recording"),
        ],
        facilities=[
            ob.facility(
                "instrument_store",
                "instrument store",
                at="store_room",
                guards=["frank"],
                operations=["rehair"],
                supplies=["rosin"],
            ),
            ob.facility(
                "repair_bench",
                "repair bench",
                at="workshop",
                guards=["nell"],
                operations=["restring", "polish"],
            ),
            ob.facility(
                "recording_studio",
                "recording studio",
                at="studio",
                guards=["ada"],
                operations=["record"],
                products=["recording"],
            ),
            ob.facility(
                "stationery_cupboard",
                "stationery cupboard",
                at="office",
                guards=["ada"],
                supplies=["glue"],
            ),
        ],
        home="office",
        group=("staff", "Staff"),
    )


music_school = ob.parsed(raw_music_school)
