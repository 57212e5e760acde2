"""A small youth hostel's back office for the reader's tests of blind round 14's classes (the
round's own office and sentences were never read). A post room keeps a parcel for anyone and
Yusuf's bike pump, and its post desk sends a parcel outside by courier; a copier there prints a
rota file, laminates or shreds a notice; a kitchen keeps a kettle for anyone and makes tea and
hot chocolate; a laundry shelf keeps an iron; people own project folders, step stools, ladders,
book carts and storybooks. Some names carry diacritics (Siân, Trần Bảo Châu). No item is
called a drink or something to write with."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE: tuple[tuple[str, str, list[str], list[dict[str, Any]]], ...] = (
    ("hamid", "Hamid Rahimi", [], [{"type": "folder"}, {"type": "step_stool"}]),
    ("bea", "Bea Lindqvist", [], [{"type": "folder"}, {"type": "ladder"}]),
    ("quinn", "Ms Quinn Ashby", ["Ms Ashby"], [{"type": "folder"}]),
    ("dara", "Dara Flynn", [], [{"type": "book_cart"}, {"type": "storybook"}]),
    ("mei", "Mei Tanaka", [], [{"type": "step_stool"}, {"type": "storybook"}]),
    (
        "yusuf",
        "Yusuf Demir",
        [],
        [{"type": "pump", "at": "post_room", "facility": "post_desk"}, {"type": "ladder"}],
    ),
    ("oona", "Oona Byrne", [], [{"type": "storybook"}]),
    ("chau", "Trần Bảo Châu", [], [{"type": "storybook"}]),
    ("sian", "Siân Pryce", [], [{"type": "step_stool"}]),
)


def raw_hostel() -> dict[str, Any]:
    return {
        "name": "hostel",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0, 29.0, 33.0, 37.0), 1)
            ),
            {"id": "post_room", "kind": "facility", "name": "Post room", "x": 4.0, "y": 20.5},
            {"id": "kitchen", "kind": "facility", "name": "Kitchen", "x": 14.0, "y": 20.5},
            {"id": "laundry", "kind": "facility", "name": "Laundry", "x": 24.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "folder", "name": "project folder", "synonyms": ["folder"]},
            {"id": "step_stool", "name": "step stool"},
            {"id": "ladder", "name": "ladder"},
            {"id": "book_cart", "name": "book cart", "synonyms": ["book trolley"]},
            {"id": "storybook", "name": "storybook", "kind": "personal", "synonyms": ["book"]},
            {"id": "pump", "name": "bike pump"},
            {"id": "parcel", "name": "parcel", "synonyms": ["package"]},
            {"id": "kettle", "name": "kettle"},
            {"id": "iron", "name": "iron"},
            {"id": "rota", "name": "file", "kind": "electronic", "synonyms": ["spreadsheet"]},
            {"id": "notice", "name": "notice", "kind": "personal"},
            {"id": "printout", "name": "printout", "kind": "product"},
            {"id": "tea", "name": "tea", "kind": "product"},
            {"id": "cocoa", "name": "hot chocolate", "kind": "product"},
        ],
        "operations": [
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier", "post"],
                "input": "parcel",
                "sends_out": True,
                "destination_asked": "the name and address of the place",
            },
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "rota",
                "product": "printout",
            },
            {"id": "laminate", "name": "laminate", "verbs": ["laminate"], "input": "notice"},
            {
                "id": "shred",
                "name": "shred",
                "verbs": ["shred"],
                "input": "notice",
                "consumes": True,
            },
            {"id": "brew", "name": "make tea", "verbs": ["brew"], "product": "tea"},
            {"id": "cocoa", "name": "make hot chocolate", "product": "cocoa"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "rota"}, {"type": "notice"}],
            }
            for n, (pid, name, aliases, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "post_desk",
                "name": "post desk",
                "location": "post_room",
                "operations": ["courier"],
                "guards": ["yusuf"],
                "supplies": [{"type": "parcel", "count": 1}],
            },
            {
                "id": "copier",
                "name": "copier",
                "location": "post_room",
                "operations": ["print", "laminate", "shred"],
                "products": ["printout"],
                "guards": ["bea"],
            },
            {
                "id": "kitchen_counter",
                "name": "kitchen counter",
                "location": "kitchen",
                "operations": ["brew", "cocoa"],
                "products": ["tea", "cocoa"],
                "guards": ["oona"],
                "supplies": [{"type": "kettle"}],
            },
            {
                "id": "laundry_shelf",
                "name": "laundry shelf",
                "location": "laundry",
                "guards": ["mei"],
                "supplies": [{"type": "iron"}],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "post_room"},
    }


@functools.cache
def hostel() -> Office:
    return parse_office(raw_hostel(), "hostel")
