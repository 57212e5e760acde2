"""A football club's training ground for the reader's tests of blind rounds 23 and 24 (the
rounds' own offices and sentences were never read): a manager everyone calls the gaffer who
signs papers, a coach with a contract to be signed and a club stamp that seals, stopwatches
and a tactics board people lend, a kit room that washes kit."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("rhys", "Rhys Morgan", "mug", "contract", aliases=["gaffer"]),
    ob.person("dele", "Dele Okafor", "mug", "contract", "stopwatch"),
    ob.person("sian", "Sian Price", "mug", "stopwatch", "club_stamp"),
    ob.person("marco", "Marco Bellini", "mug", "tactics_board", "kit_bag"),
    ob.person("nell", "Nell Walsh", "mug", "scouting_file"),
    ob.person("owen", "Owen Pryce", "mug"),
)


def raw_training_ground() -> dict[str, Any]:
    return ob.office_file(
        "training ground",
        _PEOPLE,
        rooms=[ob.room("kit_room", "Kit room", 4.0, 20.5)],
        item_types=[
            ob.item("contract", "contract", "personal", signable=True),
            ob.item("club_stamp", "club stamp", seals=True),
            ob.item("stopwatch", "stopwatch"),
            ob.item("tactics_board", "tactics board"),
            ob.item("kit_bag", "kit bag", "personal"),
            ob.item("mug", "mug", "personal"),
            ob.item("scouting_file", "scouting file", "electronic"),
            ob.item("clean_kit", "clean kit", "product"),
        ],
        operations=[ob.operation("wash", "wash", input="kit_bag", product="clean_kit")],
        facilities=[
            ob.facility(
                "kit_room_washer",
                "washing machine",
                at="kit_room",
                guards=["owen"],
                operations=["wash"],
                products=["clean_kit"],
            )
        ],
        home="kit_room",
    )


training_ground = ob.parsed(raw_training_ground)
