"""An opera house's orchestra pit for the reader's tests of blind round 27 (the round's own
office and sentences were never read): a copier that prints a part (also "run off"), a
wardrobe that steams a jacket, instruments kept in a practice room whose only use is a room
to warm up in, and lunches kept in the band-room fridge; a player named like an
instrument (Viola Hart)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person(
        "ines",
        "Ines Varga",
        "jacket",
        ob.kept("cello", at="practice_room", facility="practice_room"),
        ob.kept("lunch", at="band_room", facility="fridge"),
    ),
    ob.person("teodor", "Teodor Lind", "jacket", "cello"),
    ob.person("maud", "Maud Fairley"),
    ob.person("viola", "Viola Hart", ob.kept("lunch", at="band_room", facility="fridge")),
)


def raw_orchestra_pit() -> dict[str, Any]:
    return ob.office_file(
        "orchestra pit",
        _PEOPLE,
        rooms=[
            ob.room("band_room", "Band room", 4.0, 20.0),
            ob.room("practice_room", "Practice room", 12.0, 20.0),
            ob.room("library", "Music library", 20.0, 20.0),
        ],
        item_types=[
            ob.item("part", "part", "electronic", synonyms=["score file"]),
            ob.item("printout", "printout", "product", synonyms=["copy"]),
            ob.item("jacket", "concert jacket", synonyms=["jacket", "tails"]),
            ob.item("cello", "cello", synonyms=["instrument", "viola"]),
            ob.item("lunch", "lunch", "personal"),
        ],
        operations=[
            ob.operation("print", "print", "run off", input="part", product="printout"),
            ob.operation("steam", "steam", "press", input="jacket"),
            ob.operation("warm_up", name="warm up"),
        ],
        facilities=[
            ob.facility(
                "copier",
                "library copier",
                at="library",
                guards=["maud"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "wardrobe", "wardrobe", at="band_room", guards=["maud"], operations=["steam"]
            ),
            ob.facility(
                "practice_room",
                "practice room",
                at="practice_room",
                guards=["maud"],
                operations=["warm_up"],
                synonyms=["instrument lockers"],
            ),
            ob.facility("fridge", "band-room fridge", at="band_room", guards=["maud"]),
        ],
        everyone_owns=["part"],
        home="band_room",
    )


orchestra_pit = ob.parsed(raw_orchestra_pit)
