"""A notary's office for the reader's tests of blind rounds 34-36's classes of consent,
errands outside and services asked by need (the rounds' own offices and sentences were never
read): notary stamps two colleagues own, a tape dispenser and a stapler, an affidavit and
papers everyone has, a photocopier whose product is called a "copy", a coffee machine, a
shredder (which works on papers, never on a spreadsheet), and a courier desk that sends
papers out of the office. One colleague is called by a title ("Dr Hartley")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ruth", "Ruth Okafor", "stapler", "tape"),
    ob.person("tomasz", "Tomasz Brandt", "seal", "tape"),
    ob.person("hana", "Hana Sato", "seal", "stapler"),
    ob.person("felix", "Felix Hartley", aliases=["Dr Hartley"]),
    ob.person("kwesi", "Kwesi Mensah", "tape"),
)


def raw_notary_office() -> dict[str, Any]:
    return ob.office_file(
        "notary office",
        _PEOPLE,
        everyone_owns=["document", "affidavit", "file"],
        rooms=[
            ob.room("copy_room", "Copy room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 12.0, 20.0),
            ob.room("post_room", "Post room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("seal", "notary stamp", synonyms=["stamp", "seal"], seals=True),
            ob.item("tape", "tape dispenser", synonyms=["tape"]),
            ob.item("stapler", "stapler"),
            ob.item(
                "document",
                "document",
                "personal",
                signable=True,
                synonyms=["policy", "letter", "contract"],
            ),
            ob.item("affidavit", "affidavit", "personal", signable=True),
            ob.item("file", "electronic file", "electronic", synonyms=["spreadsheet", "pdf"]),
            ob.item("coffee", "coffee", "product", synonyms=["latte"]),
            ob.item("copy", "photocopy", "product", synonyms=["copy", "copies"]),
        ],
        operations=[
            ob.operation("copy", "copy", "photocopy", input="document", product="copy"),
            ob.operation("coffee", "brew", name="make coffee", product="coffee"),
            ob.operation("shred", "shred", input="document", consumes=True),
            ob.operation(
                "courier",
                "courier",
                input="document",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            ob.facility(
                "photocopier",
                "photocopier",
                at="copy_room",
                guards=["kwesi"],
                operations=["copy"],
                products=["copy"],
            ),
            ob.facility(
                "shredder",
                "shredder",
                at="copy_room",
                guards=["kwesi"],
                operations=["shred"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["hana"],
                operations=["coffee"],
                products=["coffee"],
                synonyms=["machine"],
            ),
            ob.facility(
                "courier_desk",
                "courier desk",
                at="post_room",
                guards=["tomasz"],
                operations=["courier"],
            ),
        ],
        home="copy_room",
    )


notary_office = ob.parsed(raw_notary_office)
