"""A car dealership for the reader's tests of blind rounds 23 and 24 (the rounds' own offices
and sentences were never read): a key-cutting machine that makes a spare key from a car key,
a plate press that makes number plates from a job card, a charging bench that charges jump
packs, and a post tray that posts logbooks out."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("gary", "Gary Holt", "car_key", "job_card", "jump_pack", "logbook"),
    ob.person("priya", "Priya Shah", "car_key", "job_card", "logbook"),
    ob.person("tom", "Tom Ellis", "jump_pack"),
    ob.person("bev", "Bev Marsh", "car_key"),
)


def raw_dealership() -> dict[str, Any]:
    return ob.office_file(
        "dealership",
        _PEOPLE,
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.0),
            ob.room("front_desk", "Front desk", 20.0, 20.0),
        ],
        item_types=[
            ob.item("car_key", "car key", synonyms=["key"]),
            ob.item("jump_pack", "jump pack", synonyms=["jump starter"]),
            ob.item("job_card", "job card", "personal"),
            ob.item("logbook", "logbook", "personal", synonyms=["v5"]),
            ob.item("spare_key", "spare key", "product"),
            ob.item("number_plate", "number plate", "product", synonyms=["plate", "plates"]),
        ],
        operations=[
            ob.operation("cut", "cut", input="car_key", product="spare_key"),
            ob.operation("press", "press", input="job_card", product="number_plate"),
            ob.operation("charge", "charge", "recharge", input="jump_pack"),
            ob.operation(
                "post",
                "post",
                input="logbook",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            ob.facility(
                "key_machine",
                "key-cutting machine",
                at="workshop",
                guards=["tom"],
                operations=["cut"],
                products=["spare_key"],
            ),
            ob.facility(
                "plate_press",
                "plate press",
                at="workshop",
                guards=["tom"],
                operations=["press"],
                products=["number_plate"],
            ),
            ob.facility(
                "charging_bench",
                "charging bench",
                at="workshop",
                guards=["tom"],
                operations=["charge"],
            ),
            ob.facility(
                "post_tray", "post tray", at="front_desk", guards=["bev"], operations=["post"]
            ),
        ],
        home="front_desk",
    )


dealership = ob.parsed(raw_dealership)
