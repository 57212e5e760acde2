"""A theatre company's production office for the reader's tests of blind round 8's classes
(the round's own office and sentences were never read). Two pairs of people whose one-word
names sound alike (Ann Mbeki and Roseanne Vale, called Anne; Jon Petrov and Jonathan Wilde,
called John), paper contracts that are copied, couriered and faxed out, a props cupboard
that keeps cotton gloves and gaffer tape for anyone, and places that are neither people nor
facilities (the green room, the stage door)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ann", "Ann Mbeki", "torch", "contract"),
    ob.person("roseanne", "Roseanne Vale", "tape_measure", "contract", aliases=["Anne"]),
    ob.person("jon", "Jon Petrov", "torch", "contract", "lanyard"),
    ob.person("jonathan", "Jonathan Wilde", "lanyard", "contract", aliases=["John"]),
    ob.person("oona", "Oona Beck", "tape_measure", "contract"),
    ob.person("dev", "Dev Kapoor", "torch", "contract", aliases=["Devraj"]),
)


def raw_playhouse() -> dict[str, Any]:
    return ob.office_file(
        "playhouse",
        _PEOPLE,
        everyone_owns=["rota"],
        desks=ob.desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        rooms=[
            ob.room("print_nook", "Print nook", 4.0, 18.0),
            ob.room("store_room", "Store room", 12.0, 18.0),
            ob.room("stage_door", "Stage door", 20.0, 18.0),
            ob.room("green_room", "Green room", 28.0, 18.0, kind="room"),
        ],
        item_types=[
            ob.item("torch", "torch", synonyms=["flashlight"]),
            ob.item("tape_measure", "tape measure"),
            ob.item("lanyard", "lanyard", synonyms=["pass"]),
            ob.item("cotton_gloves", "cotton gloves", synonyms=["white gloves"]),
            ob.item("gaffer_tape", "gaffer tape", consumable=True, mass=True),
            ob.item(
                "contract", "contract", "personal", signable=True, synonyms=["agreement", "rider"]
            ),
            ob.item("rota", "rota", "electronic", synonyms=["schedule"]),
            ob.item("printout", "printout", "product"),
            ob.item("copy", "photocopy", "product", synonyms=["copy"]),
        ],
        operations=[
            ob.operation("print", "print", input="rota", product="printout"),
            ob.operation("copy", "copy", "photocopy", input="contract", product="copy"),
            ob.operation("courier", "courier", input="contract", sends_out=True),
            ob.operation("fax", "fax", input="contract", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "copier", "copier", at="print_nook", guards=["oona"], operations=["print", "copy"]
            ),
            ob.facility(
                "props_cupboard",
                "props cupboard",
                at="store_room",
                guards=["dev"],
                supplies=["cotton_gloves", "gaffer_tape"],
                synonyms=["cupboard"],
            ),
            ob.facility(
                "courier_desk",
                "courier desk",
                at="stage_door",
                guards=["jon"],
                operations=["courier"],
            ),
            ob.facility(
                "fax_machine", "fax machine", at="print_nook", guards=["oona"], operations=["fax"]
            ),
        ],
        home="print_nook",
        group=("company", "Company"),
    )


playhouse = ob.parsed(raw_playhouse)
