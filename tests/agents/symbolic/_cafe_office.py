"""A small office of rooms said by the room their names open with ("Café counter" and "Café
kitchen", "Post room counter", "Kitchen counter"), with a blender, a coffee machine and a
polishing bench, and a watch repair and a framing service that send things out and ask where,
for the reader's tests of a place said by the first words of its name and of a send-out asked
with its purpose."""

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
        "Corner works",
        [person("ana", "Ana Diaz", "watch"), person("ben", "Ben Hart"), person("cy", "Cy Moss")],
        rooms=[
            room("cafe_counter", "Café counter", 20.0, 10.0, kind="workstation"),
            room("cafe_kitchen", "Café kitchen", 24.0, 10.0),
            room("post_counter", "Post room counter", 28.0, 10.0),
            room("kitchen_counter", "Kitchen counter", 32.0, 10.0),
            room("dock", "Charging dock", 1.0, 1.0, kind="room"),
        ],
        item_types=[
            item("shake", "protein shake", "product", synonyms=["shake", "smoothie"]),
            item("coffee", "coffee", "product", synonyms=["latte"]),
            item("stapler", "stapler"),
            item("pen", "pen"),
            item("watch", "watch", "personal"),
            item("certificate", "certificate", "personal"),
        ],
        operations=[
            operation("blend", "blend", name="blend a shake", product="shake"),
            operation("brew", "brew", name="make coffee", product="coffee"),
            operation(
                "repair",
                "repair",
                name="repair",
                input="watch",
                sends_out=True,
                destination_asked="which repairer to send it to",
                done="sent off for repair",
            ),
            operation("polish", "polish", name="polish", input="watch", done="polished"),
            operation(
                "frame",
                "frame",
                name="frame",
                input="certificate",
                sends_out=True,
                destination_asked="which framer to send it to",
                done="sent off for framing",
            ),
        ],
        facilities=[
            facility(
                "blender",
                "blender",
                at="cafe_kitchen",
                guards=["cy"],
                operations=["blend"],
                products=["shake"],
            ),
            facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen_counter",
                guards=["cy"],
                operations=["brew"],
                products=["coffee"],
            ),
            facility(
                "repair_tray",
                "repair tray",
                at="post_counter",
                guards=["ben"],
                operations=["repair"],
            ),
            facility("bench", "polishing bench", at="dock", guards=["cy"], operations=["polish"]),
            facility(
                "frame_tray", "frame tray", at="post_counter", guards=["ben"], operations=["frame"]
            ),
            facility(
                "cupboard",
                "cupboard",
                at="post_counter",
                guards=["ben"],
                supplies=["stapler", "pen"],
            ),
        ],
        home="dock",
        everyone_owns=["certificate"],
    )


cafe_office = parsed(_raw)
read_as_ana = frame_reader(cafe_office, "ana")
