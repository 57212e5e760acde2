"""A small workshop's office for the reader's tests of services said by nouns, through a
facility, or not offered at all (fixer 189b; the round's own offices and sentences were never
read).

- Ola keeps the glazing machine ("glazer"), which glazes job trays, and the house stamp, a
  seal item that stamps papers such as valuations.
- Ben keeps the repair bench, which restrings rackets and sharpens knives.
- Nothing here lacquers, varnishes, tunes or polishes; several people own trays, rackets,
  knives and valuations.
"""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ola", "Ola Berg", "stamp", "tray"),
    ob.person("ben", "Ben Achterberg", "racket", "knife"),
    ob.person("lee", "Lee Marsh", "tray", "racket", "knife", "valuation"),
    ob.person("sam", "Sam Kowal", "tray", "valuation", "violin"),
)


def raw_glaze_works() -> dict[str, Any]:
    return ob.office_file(
        "glaze_works",
        _PEOPLE,
        rooms=[
            ob.room("kiln_room", "Kiln room", 6.0, 18.0),
            ob.room("workshop", "Workshop", 14.0, 18.0),
            ob.room("office", "Office", 22.0, 18.0),
        ],
        item_types=[
            ob.item("tray", "job tray", synonyms=["tray"]),
            ob.item("racket", "racket"),
            ob.item("knife", "knife"),
            ob.item("violin", "violin", synonyms=["fiddle"]),
            ob.item("valuation", "valuation", "personal", signable=True),
            ob.item("stamp", "house stamp", seals=True, synonyms=["stamp"]),
        ],
        operations=[
            ob.operation("glaze", "glaze", input="tray"),
            ob.operation("restring", "restring", input="racket"),
            ob.operation("sharpen", "sharpen", "hone", input="knife"),
        ],
        facilities=[
            ob.facility(
                "glazer",
                "glazing machine",
                at="kiln_room",
                guards=["ola"],
                operations=["glaze"],
                synonyms=["glazer"],
            ),
            ob.facility(
                "repair_bench",
                "repair bench",
                at="workshop",
                guards=["ben"],
                operations=["restring", "sharpen"],
            ),
        ],
        home="office",
        group=("staff", "Staff"),
    )


glaze_works = ob.parsed(raw_glaze_works)
