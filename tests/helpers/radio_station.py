"""A small community radio station for the reader's tests of polite indirect requests and of
operations named by a noun phrase (no blind round's office or sentences were read). A supply
cupboard keeps glue sticks and marker pens; a proofing desk proofreads a script; a legal desk
runs a legal review ("vet") on a contract; a laminator laminates a poster (each comes back
changed); ordinary belongings (a headset, a van key)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("wren", "Wren Okafor", "headset", "script", "poster"),
    ob.person("basil", "Basil Novak", "van_key", "contract"),
    ob.person("odile", "Odile Marsh", "headset", "script"),
    ob.person("teodor", "Teodor Haas", "contract", "poster"),
    ob.person(
        "linnea",
        "Linnea Brandt",
        "script",
        ob.kept("glue_stick", at="store_room", facility="supply_cupboard"),
        ob.kept("marker_pen", at="store_room", facility="supply_cupboard"),
    ),
)


def raw_radio_station() -> dict[str, Any]:
    return ob.office_file(
        "radio_station",
        _PEOPLE,
        rooms=[
            ob.room("store_room", "Store room", 4.0, 20.5),
            ob.room("back_office", "Back office", 18.0, 20.5),
        ],
        item_types=[
            ob.item("headset", "headset"),
            ob.item("van_key", "van key", synonyms=["van keys"]),
            ob.item("glue_stick", "glue stick"),
            ob.item("marker_pen", "marker pen"),
            ob.item("script", "script", "personal", synonyms=["show script"]),
            ob.item("contract", "contract", "personal"),
            ob.item("poster", "poster", "personal"),
        ],
        operations=[
            ob.operation("proof", "proofread", name="proofread", input="script"),
            ob.operation("vet", "vet", name="legal review", input="contract"),
            ob.operation("laminate", "laminate", input="poster"),
        ],
        facilities=[
            ob.facility("supply_cupboard", "supply cupboard", at="store_room", guards=["linnea"]),
            ob.facility(
                "proof_desk",
                "proofing desk",
                at="back_office",
                guards=["odile"],
                operations=["proof"],
            ),
            ob.facility(
                "legal_desk", "legal desk", at="back_office", guards=["basil"], operations=["vet"]
            ),
            ob.facility(
                "laminator",
                "laminator",
                at="store_room",
                guards=["teodor"],
                operations=["laminate"],
            ),
        ],
        home="store_room",
    )


radio_station = ob.parsed(raw_radio_station)
