"""A rigging loft for the tests of what asks and what only tells: a colleague whose given name
is an ordinary word (Gale), a courier service called "van run" that sends a parcel out, and a
shredder, a laminator and a splicing bench (services whose names may be a message's topic),
and a stores cupboard that hands out gloves, tape and rulers."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("gale", "Gale Pryce", "glove", aliases=["Gale"]),
    ob.person("dewi", "Dewi Rhys", "rope"),
    ob.person("nia", "Nia Evans", "glove"),
    ob.person("owen", "Owen Bevan"),
)


def raw_rigging_loft() -> dict[str, Any]:
    return ob.office_file(
        "rigging loft",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Stores", 4.0, 20.0),
            ob.room("bench_room", "Bench room", 12.0, 20.0),
        ],
        item_types=[
            ob.item("parcel", "parcel", "personal"),
            ob.item("draft", "draft", "personal"),
            ob.item("card", "card", "personal"),
            ob.item("rope", "rope"),
            ob.item("glove", "gloves", synonyms=["glove", "work gloves"]),
            ob.item("tape", "tape", synonyms=["sticky tape"]),
            ob.item("ruler", "ruler"),
            ob.item("sheet", "laminated card", "product"),
        ],
        operations=[
            ob.operation("shred", "shred", input="draft", consumes=True),
            ob.operation("laminate", "laminate", input="card", product="sheet"),
            ob.operation("splice", "splice", input="rope"),
            ob.operation("courier", "courier", name="van run", input="parcel", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "shredder", "shredder", at="bench_room", guards=["owen"], operations=["shred"]
            ),
            ob.facility(
                "laminator", "laminator", at="bench_room", guards=["owen"], operations=["laminate"]
            ),
            ob.facility(
                "bench", "splicing bench", at="bench_room", guards=["dewi"], operations=["splice"]
            ),
            ob.facility("van", "van run", at="stores", guards=["owen"], operations=["courier"]),
            ob.facility(
                "store",
                "stores",
                at="stores",
                guards=["nia"],
                supplies=[
                    {"type": "glove", "count": 5},
                    {"type": "tape", "count": 5},
                    {"type": "ruler", "count": 2},
                ],
                synonyms=["cupboard", "supply cupboard"],
            ),
        ],
        everyone_owns=["parcel", "draft", "card"],
        home="stores",
    )


rigging_loft = ob.parsed(raw_rigging_loft)
