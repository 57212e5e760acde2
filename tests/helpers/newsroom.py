"""A small regional newsroom for the reader's tests of blind round 16's classes (the round's
own office and sentences were never read). A legal desk gives a page proof a "legal read"
(it comes back); a dispatch desk sends proofs out with a courier to a place outside the
office (asked "which printing works it should go to"); a print room prints a file; a
stationery cupboard keeps reporter's notebooks and pens for anyone; a kitchen makes coffee
and tea (plain only); a managing editor stamps with the desk stamp; a post room takes what is
left for the post. ``newsroom()`` is the office; ``raw_newsroom()`` its dictionary, for a test
that needs a variant."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office
from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "page_proof", "lanyard"),
    ob.person("tomas", "Tomas Reyes", "page_proof", "desk_stamp"),
    ob.person("femi", "Femi Adeyemi", "page_proof"),
    ob.person("marta", "Marta Lindqvist", "page_proof", "lanyard"),
    ob.person("oskar", "Oskar Brandt", "page_proof"),
    ob.person("hana", "Hana Sato"),
)


def raw_newsroom(*, style_desk: bool = False) -> dict[str, Any]:
    """The office's dictionary; ``style_desk``: a subs desk also gives proofs a "style read"
    (two operations then share the head noun "read" of their names)."""
    raw = _raw()
    if style_desk:
        raw["operations"].append(
            ob.operation("subedit", "subedit", name="style read", input="page_proof")
        )
        raw["facilities"].append(
            ob.facility(
                "subs_desk", "subs desk", at="back_office", guards=["femi"], operations=["subedit"]
            )
        )
    return raw


def _raw() -> dict[str, Any]:
    return ob.office_file(
        "newsroom",
        _PEOPLE,
        everyone_owns=["agenda"],
        rooms=[
            ob.room("back_office", "Back office", 6.0, 20.5),
            ob.room("post_room", "Post room", 14.0, 20.5),
            ob.room("kitchen", "Kitchen", 22.0, 20.5),
        ],
        item_types=[
            ob.item("page_proof", "page proof", "personal", signable=True, synonyms=["proof"]),
            ob.item("lanyard", "lanyard"),
            ob.item("desk_stamp", "desk stamp", seals=True),
            ob.item("notebook", "reporter's notebook", consumable=True),
            ob.item("pen", "pen", consumable=True),
            ob.item("agenda", "agenda", "electronic"),
            ob.item("printout", "printout", "product"),
            ob.item("coffee", "coffee", "product"),
            ob.item("tea", "tea", "product"),
        ],
        operations=[
            ob.operation("vet", "vet", name="legal read", input="page_proof"),
            ob.operation(
                "courier",
                "courier",
                input="page_proof",
                sends_out=True,
                destination_asked="which printing works it should go to",
                done="sent with the courier",
            ),
            ob.operation("print", "print", input="agenda", product="printout"),
            ob.operation("brew", "brew", name="make coffee", product="coffee"),
            ob.operation("steep", "steep", name="make tea", product="tea"),
        ],
        facilities=[
            ob.facility(
                "legal_desk", "legal desk", at="back_office", guards=["oskar"], operations=["vet"]
            ),
            ob.facility(
                "dispatch",
                "dispatch desk",
                at="post_room",
                guards=["hana"],
                operations=["courier"],
            ),
            ob.facility("post_room_tray", "post room", at="post_room", guards=["hana"]),
            ob.facility(
                "print_room",
                "print room",
                at="back_office",
                guards=["oskar"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "cupboard",
                "stationery cupboard",
                synonyms=["cupboard"],
                at="back_office",
                guards=["oskar"],
                supplies=["notebook", "pen"],
            ),
            ob.facility(
                "kitchen_counter",
                "kitchen counter",
                at="kitchen",
                guards=["marta"],
                operations=["brew", "steep"],
                products=["coffee", "tea"],
            ),
        ],
        home="back_office",
    )


newsroom = ob.parsed(raw_newsroom)


@functools.cache
def newsroom_with_style_desk() -> Office:
    return parse_office(raw_newsroom(style_desk=True), "newsroom-style-desk")
