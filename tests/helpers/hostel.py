"""A small youth hostel's back office for the reader's tests of blind round 14's classes (the
round's own office and sentences were never read). A post room keeps a parcel for anyone and
Yusuf's bike pump, and its post desk sends a parcel outside by courier; a copier there prints a
rota file, laminates or shreds a notice; a kitchen keeps a kettle for anyone and makes tea and
hot chocolate; a laundry shelf keeps an iron; people own project folders, step stools, ladders,
book carts and storybooks. Some names carry diacritics (Siân, Trần Bảo Châu). No item is
called a drink or something to write with."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    ASKS_NAME_AND_ADDRESS,
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
    person("hamid", "Hamid Rahimi", "folder", "step_stool"),
    person("bea", "Bea Lindqvist", "folder", "ladder"),
    person("quinn", "Ms Quinn Ashby", "folder", aliases=["Ms Ashby"]),
    person("dara", "Dara Flynn", "book_cart", "storybook"),
    person("mei", "Mei Tanaka", "step_stool", "storybook"),
    person("yusuf", "Yusuf Demir", kept("pump", at="post_room", facility="post_desk"), "ladder"),
    person("oona", "Oona Byrne", "storybook"),
    person("chau", "Trần Bảo Châu", "storybook"),
    person("sian", "Siân Pryce", "step_stool"),
)


def raw_hostel() -> dict[str, Any]:
    return office_file(
        "hostel",
        _PEOPLE,
        everyone_owns=["rota", "notice"],
        rooms=[
            room("post_room", "Post room", 4.0, 20.5),
            room("kitchen", "Kitchen", 14.0, 20.5),
            room("laundry", "Laundry", 24.0, 20.5),
        ],
        item_types=[
            item("folder", "project folder", synonyms=["folder"]),
            item("step_stool", "step stool"),
            item("ladder", "ladder"),
            item("book_cart", "book cart", synonyms=["book trolley"]),
            item("storybook", "storybook", "personal", synonyms=["book"]),
            item("pump", "bike pump"),
            item("parcel", "parcel", synonyms=["package"]),
            item("kettle", "kettle"),
            item("iron", "iron"),
            item("rota", "file", "electronic", synonyms=["spreadsheet"]),
            item("notice", "notice", "personal"),
            item("printout", "printout", "product"),
            item("tea", "tea", "product"),
            item("cocoa", "hot chocolate", "product"),
        ],
        operations=[
            operation(
                "courier",
                "courier",
                "post",
                input="parcel",
                sends_out=True,
                destination_asked=ASKS_NAME_AND_ADDRESS,
            ),
            operation("print", "print", input="rota", product="printout"),
            operation("laminate", "laminate", input="notice"),
            operation("shred", "shred", input="notice", consumes=True),
            operation("brew", "brew", name="make tea", product="tea"),
            operation("cocoa", name="make hot chocolate", product="cocoa"),
        ],
        facilities=[
            facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["yusuf"],
                operations=["courier"],
                supplies=[{"type": "parcel", "count": 1}],
            ),
            facility(
                "copier",
                "copier",
                at="post_room",
                guards=["bea"],
                operations=["print", "laminate", "shred"],
                products=["printout"],
            ),
            facility(
                "kitchen_counter",
                "kitchen counter",
                at="kitchen",
                guards=["oona"],
                operations=["brew", "cocoa"],
                products=["tea", "cocoa"],
                supplies=["kettle"],
            ),
            facility(
                "laundry_shelf", "laundry shelf", at="laundry", guards=["mei"], supplies=["iron"]
            ),
        ],
        home="post_room",
    )


hostel = parsed(raw_hostel)
