"""A small surveying office for the reader's tests of blind rounds 65-66's classes (the
rounds' own offices and sentences were never read): colleagues whose given names are also
English verbs (Drew, Mark, Sue, Chase, Bob), a wax station that waxes a tube, and each
person's report, form and lunch."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("drew", "Drew Okafor", "report", "mug", "lunch", aliases=["Drew"]),
    ob.person("mark", "Mark Hollis", "report", "tube", aliases=["Mark"]),
    ob.person("sue", "Sue Amari", "mug", "tube", aliases=["Sue"]),
    ob.person("chase", "Chase Bello", "report", "lunch", aliases=["Chase"]),
    ob.person("bob", "Bob Varga", "mug", aliases=["Bob"]),
    ob.person("ines", "Ines Dahl", "report", "mug", "tube", "tape"),
)


def raw_verb_names() -> dict[str, Any]:
    return ob.office_file(
        "verb names",
        _PEOPLE,
        rooms=[
            ob.room("plan_room", "Plan room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item("report", "report", "personal", synonyms=["survey report"]),
            ob.item("form", "form", "personal", signable=True),
            ob.item("mug", "mug", synonyms=["cup"]),
            ob.item("lunch", "lunch", "personal"),
            ob.item("tube", "drawing tube", synonyms=["tube"]),
            ob.item("tape", "tape measure"),
            ob.item("waxed", "waxed tube", "product"),
        ],
        operations=[ob.operation("wax", "wax", input="tube", product="waxed")],
        facilities=[
            ob.facility(
                "wax_station", "wax station", at="plan_room", guards=["ines"], operations=["wax"]
            ),
        ],
        everyone_owns=["form"],
        home="plan_room",
    )


verb_names = ob.parsed(raw_verb_names)
