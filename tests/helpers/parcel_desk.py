"""A studio office for the reader's tests of blind round 38's classes on corrections and whose
thing (the round's own office and sentences were never read): calculators and dev kits several
people own, a hyphenated given name (Anne-Marie), a given name that is another colleague's family
name (Miles Okafor and Nadia Miles), and a weighing service on parcels only some people have."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("olive", "Olive Brandt", "calculator", "parcel"),
    ob.person("annemarie", "Anne-Marie Coyle", "calculator", "dev_kit"),
    ob.person("miles", "Miles Okafor", "dev_kit", "calculator"),
    ob.person("nadia", "Nadia Miles", "parcel"),
    ob.person("petra", "Petra Holm", "stapler", "calculator"),
)


def raw_parcel_desk() -> dict[str, Any]:
    return ob.office_file(
        "parcel desk",
        _PEOPLE,
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.0),
            ob.room("hall", "Hall", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("calculator", "calculator"),
            ob.item("dev_kit", "dev kit"),
            ob.item("parcel", "parcel", synonyms=["package"]),
            ob.item("stapler", "stapler"),
        ],
        operations=[ob.operation("weigh", "weigh", input="parcel")],
        facilities=[
            ob.facility(
                "scales", "parcel scales", at="post_room", guards=["petra"], operations=["weigh"]
            ),
        ],
        everyone_owns=["file"],
        home="hall",
    )


parcel_desk = ob.parsed(raw_parcel_desk)
