"""A drafting office for the tests of blind rounds 34-36's statement classes (those rounds' own
offices and sentences were never read): a laminator and a binder (a facility named from its
operation's verb, "bind"), a scanner that makes a PDF of a paper thing, a post desk that sends
parcels out by courier, a vending machine that sells snacks and a coffee machine that makes
coffee, a stapler and a tape dispenser people own, and spare tape kept as a consumable."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("odile", "Odile Marsh", "stapler", "tape", "certificate"),
    ob.person("piet", "Piet Vos", "stapler", "ruler", "certificate"),
    ob.person("rena", "Rena Holt", "ruler", "tape"),
    ob.person("sully", "Sully Crane", "stapler"),
    ob.person("ezra", "Ezra Lund", "ruler", "certificate"),
)


def raw_drafting_office() -> dict[str, Any]:
    return ob.office_file(
        "drafting office",
        _PEOPLE,
        rooms=[
            ob.room("copy_room", "Copy room", 4.0, 20.0),
            ob.room("post_room", "Post room", 12.0, 20.0),
            ob.room("break_room", "Break room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document", "drawing file"]),
            ob.item("certificate", "certificate", "personal", synonyms=["permit"]),
            ob.item("stapler", "stapler"),
            ob.item("ruler", "ruler"),
            ob.item("tape", "tape", consumable=True, synonyms=["sticky tape"]),
            ob.item("sheet", "laminated sheet", "product"),
            ob.item("bound_copy", "bound copy", "product"),
            ob.item("pdf", "scanned pdf", "product", synonyms=["scan", "pdf"]),
            ob.item("snack", "snack", "product", synonyms=["crisps"]),
            ob.item("coffee", "coffee", "product"),
        ],
        operations=[
            ob.operation("laminate", "laminate", input="certificate", product="sheet"),
            ob.operation("bind", "bind", input="file", product="bound_copy"),
            ob.operation("scan", "scan", input="certificate", product="pdf"),
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                input="certificate",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("vend", "buy", name="buy a snack", product="snack"),
            ob.operation("brew", "brew", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "laminator", "laminator", at="copy_room", guards=["sully"], operations=["laminate"]
            ),
            ob.facility("binder", "binder", at="copy_room", guards=["sully"], operations=["bind"]),
            ob.facility(
                "scanner",
                "scanner",
                at="copy_room",
                guards=["sully"],
                operations=["scan"],
                products=["pdf"],
            ),
            ob.facility(
                "post_desk", "post desk", at="post_room", guards=["ezra"], operations=["courier"]
            ),
            ob.facility(
                "vending_machine",
                "vending machine",
                at="break_room",
                guards=["rena"],
                operations=["vend"],
                products=["snack"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="break_room",
                guards=["rena"],
                operations=["brew"],
                products=["coffee"],
            ),
        ],
        everyone_owns=["file"],
        home="copy_room",
    )


drafting_office = ob.parsed(raw_drafting_office)
