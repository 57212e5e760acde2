"""A school media cupboard for the reader's tests of blind rounds 59-64's class on item words
said clipped or as a compound written another way ("pic" for the picture, "spec" for the
specification, "mic" for the microphone; "walkie talkie", "walkie-talkie", "walkietalkie"; the
rounds' own offices and sentences were never read): a microphone and a microscope share their
first three letters, a cartridge sits beside a car park, and a fridge is only a fridge."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("remi", "Remi Okafor", "microphone", "walkie_talkie", "picture"),
    ob.person("sasha", "Sasha Bell", "specification", "cartridge", "microscope"),
    ob.person("ivo", "Ivo Marsh", "head_torch"),
    ob.person("pat", "Pat Quinn"),
)


def raw_media_cupboard() -> dict[str, Any]:
    return ob.office_file(
        "media cupboard",
        _PEOPLE,
        rooms=[
            ob.room("media_room", "Media room", 4.0, 20.0),
            ob.room("science_lab", "Science lab", 12.0, 20.0),
            ob.room("car_park", "Car park", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item("microphone", "microphone"),
            ob.item("microscope", "microscope"),
            ob.item("walkie_talkie", "walkie-talkie"),
            ob.item("picture", "picture"),
            ob.item("specification", "specification", "personal"),
            ob.item("cartridge", "cartridge"),
            ob.item("head_torch", "head torch"),
            ob.item("fridge", "fridge"),
        ],
        operations=[],
        facilities=[],
        home="media_room",
    )


media_cupboard = ob.parsed(raw_media_cupboard)


def raw_sound_cupboard() -> dict[str, Any]:
    """The same cupboard with no microscope: "mic" clips only the microphone."""
    raw = raw_media_cupboard()
    raw["item_types"] = [t for t in raw["item_types"] if t["id"] != "microscope"]
    for person in raw["people"]:
        person["owns"] = [o for o in person.get("owns", []) if o.get("type") != "microscope"]
    return raw


sound_cupboard = ob.parsed(raw_sound_cupboard)
