"""A small firm's mailing room for the reader's tests of outsiders named by a title (blind
round 139's class; its own office and sentences were never read): a post desk two people look
after sends a document or a parcel out (verbs "post", "courier", "send out"), a print room
prints, photocopies, scans and laminates (products printout, photocopy, scan), a front desk
books a slot and hands out its card; colleagues own a stapler, a booking form and a letter."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nadia", "Nadia Haddad", "form", "stapler"),
    ob.person("tom", "Tom Price", "stapler"),
    ob.person("ines", "Ines Walker"),
    ob.person("owen", "Owen Blake"),
    ob.person("lucy", "Lucy Chen"),
    ob.person("raj", "Raj Mehta"),
)


def raw_mailing_room() -> dict[str, Any]:
    return ob.office_file(
        "mailing room",
        _PEOPLE,
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.0),
            ob.room("print_room", "Print room", 12.0, 20.0),
            ob.room("front_desk", "Front desk", 20.0, 20.0),
        ],
        item_types=[
            ob.item(
                "document",
                "document",
                "personal",
                synonyms=["contract", "report", "letter", "parcel"],
            ),
            ob.item("form", "booking form", "personal", synonyms=["form"]),
            ob.item("stapler", "stapler"),
            ob.item("printout", "printout", "product"),
            ob.item("photocopy", "photocopy", "product", synonyms=["copy"]),
            ob.item("scan", "scan", "product", synonyms=["scanned copy"]),
            ob.item("card", "appointment card", "product", synonyms=["card"]),
        ],
        operations=[
            ob.operation(
                "post",
                "post",
                "courier",
                name="send out",
                input="document",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("print", "print", input="document", product="printout"),
            ob.operation("copy", "copy", "photocopy", input="document", product="photocopy"),
            ob.operation("scan", "scan", input="document", product="scan"),
            ob.operation("laminate", "laminate", input="document"),
            ob.operation("book", "book", name="book a slot", product="card"),
        ],
        facilities=[
            ob.facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["ines", "raj"],
                operations=["post"],
            ),
            ob.facility(
                "print_room",
                "print room",
                at="print_room",
                guards=["lucy", "raj"],
                operations=["print", "copy", "scan", "laminate"],
                products=["printout", "photocopy", "scan"],
            ),
            ob.facility(
                "front_desk",
                "front desk",
                at="front_desk",
                guards=["owen"],
                operations=["book"],
                products=["card"],
            ),
        ],
        everyone_owns=["document"],
        home="post_room",
    )


mailing_room = ob.parsed(raw_mailing_room)
