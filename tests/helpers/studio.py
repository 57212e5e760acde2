"""A small architecture and photo studio for the tests of composed parts (issue 23, fix14c):
rolls of film kept at a facility (one in the picture archive, one in the fridge, both in the
store room; one on its owner's desk), a darkroom that develops a roll into photo prints (an
operation that makes a product from an item, the ``copy`` kind), a post desk that couriers a
drawing set outside the office (an operation that sends the item out), a signer with a
title, and a stamp two people own."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from helpers import office_builder as ob

_IN_ARCHIVE = ob.kept("film", at="store_room", facility="picture_archive")
_IN_FRIDGE = ob.kept("film", at="store_room", facility="fridge")
_PEOPLE = (
    ob.person("ada", "Ada Lindqvist", _IN_ARCHIVE, "drawings"),
    ob.person("bo", "Bo Farrow", _IN_FRIDGE, "drawings"),
    ob.person("cyrus", "Cyrus Mehta", "film", "drawings"),
    ob.person("amara", "Amara Osei", "drawings", "stamp"),
    ob.person("otto", "Otto Brandt", "tape_measure"),
    ob.person("kai", "Kai Nakamura", "tape_measure"),
    ob.person("pia", "Pia Holm", "stamp"),
    ob.person("sven", "Sven Aalto", "drawings"),
    ob.person("luc", "Luc Perrin"),
)


def raw_studio() -> dict[str, Any]:
    return ob.office_file(
        "studio",
        _PEOPLE,
        everyone_owns=["file"],
        desks=[*ob.desk_row(8), (5.0, 13.0)],
        rooms=[
            ob.room("store_room", "Store room", 11.0, 20.5),
            ob.room("lab", "Lab", 23.0, 20.5),
            ob.room("front_desk", "Front desk", 37.0, 20.5),
        ],
        item_types=[
            ob.item("tape_measure", "tape measure"),
            ob.item("film", "roll of film", "personal", synonyms=["film"]),
            ob.item(
                "drawings", "drawing set", "personal", signable=True, synonyms=["drawings", "plans"]
            ),
            ob.item("stamp", "approval stamp", seals=True, synonyms=["stamp"]),
            ob.item("file", "file", "electronic"),
            ob.item("photo_prints", "photo prints", "product", synonyms=["prints"]),
        ],
        operations=[
            ob.operation("develop", "develop", input="film", product="photo_prints"),
            ob.operation(
                "courier",
                "courier",
                "send out",
                input="drawings",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
                done="couriered",
            ),
        ],
        facilities=[
            ob.facility("picture_archive", "picture archive", at="store_room", guards=["otto"]),
            ob.facility("fridge", "fridge", at="store_room", guards=["kai"]),
            ob.facility(
                "darkroom",
                "darkroom",
                at="lab",
                guards=["pia", "sven"],
                operations=["develop"],
                products=["photo_prints"],
            ),
            ob.facility(
                "post_desk", "post desk", at="front_desk", guards=["luc"], operations=["courier"]
            ),
        ],
        home="front_desk",
    )


studio = ob.parsed(raw_studio)


def write_studio(path: Path) -> Path:
    """The studio as an office file, for the command line (``--office``)."""
    return ob.write_office(raw_studio(), path)
