"""A theatre company's production office for the reader's tests of blind round 8's classes
(the round's own office and sentences were never read). Two pairs of people whose one-word
names sound alike (Ann Mbeki and Roseanne Vale, called Anne; Jon Petrov and Jonathan Wilde,
called John), paper contracts that are copied, couriered and faxed out, a props cupboard
that keeps cotton gloves and gaffer tape for anyone, and places that are neither people nor
facilities (the green room, the stage door)."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    desk_row,
    facility,
    item,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("ann", "Ann Mbeki", "torch", "contract"),
    person("roseanne", "Roseanne Vale", "tape_measure", "contract", aliases=["Anne"]),
    person("jon", "Jon Petrov", "torch", "contract", "lanyard"),
    person("jonathan", "Jonathan Wilde", "lanyard", "contract", aliases=["John"]),
    person("oona", "Oona Beck", "tape_measure", "contract"),
    person("dev", "Dev Kapoor", "torch", "contract", aliases=["Devraj"]),
)


def raw_playhouse() -> dict[str, Any]:
    return office_file(
        "playhouse",
        _PEOPLE,
        everyone_owns=["rota"],
        desks=desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        rooms=[
            room("print_nook", "Print nook", 4.0, 18.0),
            room("store_room", "Store room", 12.0, 18.0),
            room("stage_door", "Stage door", 20.0, 18.0),
            room("green_room", "Green room", 28.0, 18.0, kind="room"),
        ],
        item_types=[
            item("torch", "torch", synonyms=["flashlight"]),
            item("tape_measure", "tape measure"),
            item("lanyard", "lanyard", synonyms=["pass"]),
            item("cotton_gloves", "cotton gloves", synonyms=["white gloves"]),
            item("gaffer_tape", "gaffer tape", consumable=True, mass=True),
            item(
                "contract", "contract", "personal", signable=True, synonyms=["agreement", "rider"]
            ),
            item("rota", "rota", "electronic", synonyms=["schedule"]),
            item("printout", "printout", "product"),
            item("copy", "photocopy", "product", synonyms=["copy"]),
        ],
        operations=[
            operation("print", "print", input="rota", product="printout"),
            operation("copy", "copy", "photocopy", input="contract", product="copy"),
            operation("courier", "courier", input="contract", sends_out=True),
            operation("fax", "fax", input="contract", sends_out=True),
        ],
        facilities=[
            facility(
                "copier", "copier", at="print_nook", guards=["oona"], operations=["print", "copy"]
            ),
            facility(
                "props_cupboard",
                "props cupboard",
                at="store_room",
                guards=["dev"],
                supplies=["cotton_gloves", "gaffer_tape"],
                synonyms=["cupboard"],
            ),
            facility(
                "courier_desk",
                "courier desk",
                at="stage_door",
                guards=["jon"],
                operations=["courier"],
            ),
            facility(
                "fax_machine", "fax machine", at="print_nook", guards=["oona"], operations=["fax"]
            ),
        ],
        home="print_nook",
        group=("company", "Company"),
    )


playhouse = parsed(raw_playhouse)
