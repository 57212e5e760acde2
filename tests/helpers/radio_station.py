"""A small community radio station for the reader's tests of polite indirect requests and of
operations named by a noun phrase (no blind round's office or sentences were read). A supply
cupboard keeps glue sticks and marker pens; a proofing desk proofreads a script; a legal desk
runs a legal review ("vet") on a contract; a laminator laminates a poster (each comes back
changed); ordinary belongings (a headset, a van key)."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    facility,
    item,
    kept,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("wren", "Wren Okafor", "headset", "script", "poster"),
    person("basil", "Basil Novak", "van_key", "contract"),
    person("odile", "Odile Marsh", "headset", "script"),
    person("teodor", "Teodor Haas", "contract", "poster"),
    person(
        "linnea",
        "Linnea Brandt",
        "script",
        kept("glue_stick", at="store_room", facility="supply_cupboard"),
        kept("marker_pen", at="store_room", facility="supply_cupboard"),
    ),
)


def raw_radio_station() -> dict[str, Any]:
    return office_file(
        "radio_station",
        _PEOPLE,
        rooms=[
            room("store_room", "Store room", 4.0, 20.5),
            room("back_office", "Back office", 18.0, 20.5),
        ],
        item_types=[
            item("headset", "headset"),
            item("van_key", "van key", synonyms=["van keys"]),
            item("glue_stick", "glue stick"),
            item("marker_pen", "marker pen"),
            item("script", "script", "personal", synonyms=["show script"]),
            item("contract", "contract", "personal"),
            item("poster", "poster", "personal"),
        ],
        operations=[
            operation("proof", "proofread", name="proofread", input="script"),
            operation("vet", "vet", name="legal review", input="contract"),
            operation("laminate", "laminate", input="poster"),
        ],
        facilities=[
            facility("supply_cupboard", "supply cupboard", at="store_room", guards=["linnea"]),
            facility(
                "proof_desk",
                "proofing desk",
                at="back_office",
                guards=["odile"],
                operations=["proof"],
            ),
            facility(
                "legal_desk", "legal desk", at="back_office", guards=["basil"], operations=["vet"]
            ),
            facility(
                "laminator",
                "laminator",
                at="store_room",
                guards=["teodor"],
                operations=["laminate"],
            ),
        ],
        home="store_room",
    )


radio_station = parsed(raw_radio_station)
