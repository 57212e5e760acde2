"""A small office of gear (a DI box, 9V batteries, a drill, a hammer) with a send-out service
named after its vehicle ("send out on the van", at the dispatch bay), for the reader's tests
of a thing that needs a thing, an item's name said as a verb, and a service said by its
vehicle."""

from __future__ import annotations

from helpers.office_builder import (
    facility,
    item,
    office_file,
    operation,
    parsed,
    person,
    room,
)
from helpers.reading import frame_reader


def _raw() -> dict[str, object]:
    return office_file(
        "Gear studio",
        [
            person("lee", "Lee"),
            person("wang", "Wang"),
            person("maria", "Maria", "drawer_key"),
            person("zhang", "Zhang"),
        ],
        rooms=[
            room("store", "Store room", 20.0, 10.0),
            room("bay", "Dispatch bay", 30.0, 10.0),
            room("dock", "Charging dock", 1.0, 1.0, kind="room"),
        ],
        item_types=[
            item("di_box", "DI box"),
            item("battery", "9V battery", consumable=True),
            item("drill", "drill"),
            item("hammer", "hammer"),
            item("stapler", "stapler"),
            item("paper", "paper", consumable=True),
            item("printer", "printer"),
            item("contract", "contract", signable=True),
            item("drawer_key", "drawer key"),
        ],
        operations=[
            operation(
                "dispatch",
                "dispatch",
                "send out",
                name="send out on the van",
                input="contract",
                sends_out=True,
                destination_asked="the farm or customer it should go to",
                done="sent out on the van",
            )
        ],
        facilities=[
            facility(
                "store",
                "store room",
                at="store",
                guards=["zhang"],
                supplies=["di_box", "battery", "drill", "hammer", "stapler", "paper", "printer"],
            ),
            facility(
                "dispatch_bay",
                "dispatch bay",
                at="bay",
                guards=["zhang"],
                operations=["dispatch"],
                synonyms=["van bay", "outgoing vans"],
            ),
        ],
        home="dock",
        everyone_owns=["contract"],
    )


gear_office = parsed(_raw)
read_as_lee = frame_reader(gear_office, "lee")
