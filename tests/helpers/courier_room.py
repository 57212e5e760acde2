"""A solicitors' post room for the reader's tests of blind rounds 61-62's classes on services
that send things out (the rounds' own offices and sentences were never read): a courier desk
two people look after sends a document out ("send by courier", also "courier" and
"dispatch") and a print room prints one, so a destination may carry another service's word
("the print works at Felling"); an office stamp and a hole punch colleagues own (a sealing
tool and an ordinary one); a prescription; and a colleague whose name is not ASCII."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("bjorn", "Björn Åkesson", "prescription", "stapler"),
    ob.person("siobhan", "Siobhan Reilly", "office_stamp"),
    ob.person("ana", "Ana Duarte", "hole_punch", "stapler"),
    ob.person("kit", "Kit Moran"),
    ob.person("dev", "Dev Patel"),
    ob.person("ruth", "Ruth Lee", aliases=["Dr Lee"]),
)


def raw_courier_room() -> dict[str, Any]:
    return ob.office_file(
        "courier room",
        _PEOPLE,
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.0),
            ob.room("print_room", "Print room", 12.0, 20.0),
            ob.room("meeting_room", "Meeting room", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item(
                "document",
                "document",
                "personal",
                signable=True,
                synonyms=["contract", "statement", "page proof", "form", "invoice", "agenda"],
            ),
            ob.item("prescription", "prescription", "personal"),
            ob.item("office_stamp", "office stamp", synonyms=["stamp"], seals=True),
            ob.item("hole_punch", "hole punch"),
            ob.item("stapler", "stapler"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                name="send by courier",
                input="document",
                sends_out=True,
            ),
            ob.operation("print", "print", input="document", product="printout"),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="post_room",
                guards=["kit", "dev"],
                operations=["courier"],
            ),
            ob.facility(
                "print_room",
                "print room",
                at="print_room",
                guards=["dev"],
                operations=["print"],
                products=["printout"],
            ),
        ],
        everyone_owns=["document"],
        home="post_room",
    )


courier_room = ob.parsed(raw_courier_room)
