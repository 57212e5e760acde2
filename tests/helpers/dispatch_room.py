"""A small dispatch room for the reader's tests of blind round 62's classes (the round's own
offices and sentences were never read): colleagues whose given names are also words of fixed
English phrases (Miles: "miles away"; Hope: "hope so"; Frank: "to be frank"), a courier desk
that couriers a case or a form out ("courier", "dispatch"), a post service that posts a
letter, and a printer."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Park", "stapler", aliases=["Lee"]),
    ob.person("miles", "Miles Gray", "stapler", "key", aliases=["Miles"]),
    ob.person("hope", "Hope Adeyemi", "key", aliases=["Hope"]),
    ob.person("frank", "Frank Osei", "stapler", aliases=["Frank"]),
    ob.person("dana", "Dana Wu", "tape"),
)


def raw_dispatch_room() -> dict[str, Any]:
    return ob.office_file(
        "dispatch room",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Stores", 4.0, 20.0),
            ob.room("post_room", "Post room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("tape", "tape"),
            ob.item("stapler", "stapler"),
            ob.item("key", "key"),
            ob.item("battery", "battery", synonyms=["AA", "AAs"]),
            ob.item("coffee", "coffee", "product"),
            ob.item("case", "case"),
            ob.item("form", "form", "personal", signable=True),
            ob.item("contract", "contract", "personal"),
            ob.item("letter", "letter", "personal"),
            ob.item("file", "file", "electronic"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                input="case",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("post", "post", name="post", input="letter", sends_out=True),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("coffee", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="post_room",
                guards=["dana"],
                operations=["courier", "post"],
            ),
            ob.facility(
                "printer", "printer", at="post_room", guards=["dana"], operations=["print"]
            ),
            ob.facility(
                "supply_cabinet",
                "supply cabinet",
                at="stores",
                guards=["dana"],
                supplies=["tape", "battery"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="stores",
                guards=["dana"],
                operations=["coffee"],
                products=["coffee"],
            ),
        ],
        everyone_owns=["form", "contract", "letter", "file", "case"],
        home="stores",
    )


dispatch_room = ob.parsed(raw_dispatch_room)
