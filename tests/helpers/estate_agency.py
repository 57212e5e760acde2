"""A small estate agency's back office for the reader's tests of blind round 65's send-out
class (the round's own offices and sentences were never read). Its post desk sends a parcel
out by the parcel post and a document out by courier (both ``sends_out``); a copier prints a
listing file. People own documents (forms, contracts), parcels,
staplers and mugs."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nadia", "Nadia Okafor", "stapler", "mug"),
    ob.person("owen", "Owen Price", "stapler"),
    ob.person("rosa", "Rosa Medina", "mug"),
    ob.person("tariq", "Tariq Aziz", "stapler"),
)


def raw_estate_agency() -> dict[str, Any]:
    return ob.office_file(
        "estate agency",
        _PEOPLE,
        everyone_owns=["document", "parcel", "listing"],
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.5),
            ob.room("kitchen", "Kitchen", 14.0, 20.5),
        ],
        item_types=[
            ob.item("document", "document", "personal", synonyms=["form", "contract"]),
            ob.item("parcel", "parcel", synonyms=["package"]),
            ob.item("stapler", "stapler"),
            ob.item("mug", "mug"),
            ob.item("listing", "file", "electronic", synonyms=["listing"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation(
                "parcel_post",
                "post",
                name="mail out",
                input="parcel",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation(
                "courier",
                "courier",
                name="courier run",
                input="document",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("print", "print", input="listing", product="printout"),
        ],
        facilities=[
            ob.facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["owen"],
                operations=["parcel_post", "courier"],
            ),
            ob.facility(
                "copier",
                "copier",
                at="post_room",
                guards=["rosa"],
                operations=["print"],
                products=["printout"],
            ),
        ],
        home="post_room",
    )


estate_agency = ob.parsed(raw_estate_agency)
