"""A small architecture and photo studio for the tests of composed parts (issue 23, fix14c):
rolls of film kept at a facility (one in the picture archive, one in the fridge, both in the
store room; one on its owner's desk), a darkroom that develops a roll into photo prints (an
operation that makes a product from an item, the ``copy`` kind), a post desk that couriers a
drawing set outside the office (an operation that sends the item out), a signer with a
title, and a stamp two people own."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from helpers.office_builder import (
    ASKS_NAME_AND_ADDRESS,
    desk_row,
    facility,
    item,
    kept,
    office_file,
    operation,
    parsed,
    person,
    room,
    write_office,
)

_IN_ARCHIVE = kept("film", at="store_room", facility="picture_archive")
_IN_FRIDGE = kept("film", at="store_room", facility="fridge")
_PEOPLE = (
    person("ada", "Ada Lindqvist", _IN_ARCHIVE, "drawings"),
    person("bo", "Bo Farrow", _IN_FRIDGE, "drawings"),
    person("cyrus", "Cyrus Mehta", "film", "drawings"),
    person("amara", "Amara Osei", "drawings", "stamp"),
    person("otto", "Otto Brandt", "tape_measure"),
    person("kai", "Kai Nakamura", "tape_measure"),
    person("pia", "Pia Holm", "stamp"),
    person("sven", "Sven Aalto", "drawings"),
    person("luc", "Luc Perrin"),
)


def raw_studio() -> dict[str, Any]:
    return office_file(
        "studio",
        _PEOPLE,
        everyone_owns=["file"],
        desks=[*desk_row(8), (5.0, 13.0)],
        rooms=[
            room("store_room", "Store room", 11.0, 20.5),
            room("lab", "Lab", 23.0, 20.5),
            room("front_desk", "Front desk", 37.0, 20.5),
        ],
        item_types=[
            item("tape_measure", "tape measure"),
            item("film", "roll of film", "personal", synonyms=["film"]),
            item(
                "drawings", "drawing set", "personal", signable=True, synonyms=["drawings", "plans"]
            ),
            item("stamp", "approval stamp", seals=True, synonyms=["stamp"]),
            item("file", "file", "electronic"),
            item("photo_prints", "photo prints", "product", synonyms=["prints"]),
        ],
        operations=[
            operation("develop", "develop", input="film", product="photo_prints"),
            operation(
                "courier",
                "courier",
                "send out",
                input="drawings",
                sends_out=True,
                destination_asked=ASKS_NAME_AND_ADDRESS,
                done="couriered",
            ),
        ],
        facilities=[
            facility("picture_archive", "picture archive", at="store_room", guards=["otto"]),
            facility("fridge", "fridge", at="store_room", guards=["kai"]),
            facility(
                "darkroom",
                "darkroom",
                at="lab",
                guards=["pia", "sven"],
                operations=["develop"],
                products=["photo_prints"],
            ),
            facility(
                "post_desk", "post desk", at="front_desk", guards=["luc"], operations=["courier"]
            ),
        ],
        home="front_desk",
    )


studio = parsed(raw_studio)


def write_studio(path: Path) -> Path:
    """The studio as an office file, for the command line (``--office``)."""
    return write_office(raw_studio(), path)
