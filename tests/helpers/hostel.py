"""A small youth hostel's back office for the reader's tests of blind round 14's classes (the
round's own office and sentences were never read). A post room keeps a parcel for anyone and
Yusuf's bike pump, and its post desk sends a parcel outside by courier; a copier there prints a
rota file, laminates or shreds a notice; a kitchen keeps a kettle for anyone and makes tea and
hot chocolate; a laundry shelf keeps an iron; people own project folders, step stools, ladders,
book carts and storybooks. Some names carry diacritics (Siân, Trần Bảo Châu). No item is
called a drink or something to write with."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("hamid", "Hamid Rahimi", "folder", "step_stool"),
    ob.person("bea", "Bea Lindqvist", "folder", "ladder"),
    ob.person("quinn", "Ms Quinn Ashby", "folder", aliases=["Ms Ashby"]),
    ob.person("dara", "Dara Flynn", "book_cart", "storybook"),
    ob.person("mei", "Mei Tanaka", "step_stool", "storybook"),
    ob.person(
        "yusuf", "Yusuf Demir", ob.kept("pump", at="post_room", facility="post_desk"), "ladder"
    ),
    ob.person("oona", "Oona Byrne", "storybook"),
    ob.person("chau", "Trần Bảo Châu", "storybook"),
    ob.person("sian", "Siân Pryce", "step_stool"),
)


def raw_hostel() -> dict[str, Any]:
    return ob.office_file(
        "hostel",
        _PEOPLE,
        everyone_owns=["rota", "notice"],
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.5),
            ob.room("kitchen", "Kitchen", 14.0, 20.5),
            ob.room("laundry", "Laundry", 24.0, 20.5),
        ],
        item_types=[
            ob.item("folder", "project folder", synonyms=["folder"]),
            ob.item("step_stool", "step stool"),
            ob.item("ladder", "ladder"),
            ob.item("book_cart", "book cart", synonyms=["book trolley"]),
            ob.item("storybook", "storybook", "personal", synonyms=["book"]),
            ob.item("pump", "bike pump"),
            ob.item("parcel", "parcel", synonyms=["package"]),
            ob.item("kettle", "kettle"),
            ob.item("iron", "iron"),
            ob.item("rota", "file", "electronic", synonyms=["spreadsheet"]),
            ob.item("notice", "notice", "personal"),
            ob.item("printout", "printout", "product"),
            ob.item("tea", "tea", "product"),
            ob.item("cocoa", "hot chocolate", "product"),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "post",
                input="parcel",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("print", "print", input="rota", product="printout"),
            ob.operation("laminate", "laminate", input="notice"),
            ob.operation("shred", "shred", input="notice", consumes=True),
            ob.operation("brew", "brew", name="make tea", product="tea"),
            ob.operation("cocoa", name="make hot chocolate", product="cocoa"),
        ],
        facilities=[
            ob.facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["yusuf"],
                operations=["courier"],
                supplies=[{"type": "parcel", "count": 1}],
            ),
            ob.facility(
                "copier",
                "copier",
                at="post_room",
                guards=["bea"],
                operations=["print", "laminate", "shred"],
                products=["printout"],
            ),
            ob.facility(
                "kitchen_counter",
                "kitchen counter",
                at="kitchen",
                guards=["oona"],
                operations=["brew", "cocoa"],
                products=["tea", "cocoa"],
                supplies=["kettle"],
            ),
            ob.facility(
                "laundry_shelf", "laundry shelf", at="laundry", guards=["mei"], supplies=["iron"]
            ),
        ],
        home="post_room",
    )


hostel = ob.parsed(raw_hostel)
