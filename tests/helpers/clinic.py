"""A small veterinary clinic the reader's tests of this round run on: no sentence of the
default office fits it. Several people are named with ordinary words or a month (Dawn, Rich,
May, Hal, Chip, whose name is also in an item's), a fridge keeps an ice pack, a printer
makes printouts."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_DESKS = (
    (5.0, 6.0),
    (9.0, 6.0),
    (13.0, 6.0),
    (17.0, 6.0),
    (21.0, 6.0),
    (25.0, 6.0),
    (29.0, 6.0),
)
_PEOPLE = (
    ("dawn", "Dawn Ellis", [{"type": "thermometer"}, {"type": "document"}]),
    ("rich", "Rich Adeyemi", [{"type": "clipboard"}, {"type": "document"}]),
    ("may", "May Oduya", [{"type": "ice_pack", "at": "staff_room", "facility": "fridge"}]),
    ("hal", "Hal Brooks", [{"type": "thermometer"}, {"type": "document"}]),
    ("ines", "Inés Vidal", [{"type": "clipboard"}, {"type": "document"}]),
    ("tomas", "Tomás Reyes", [{"type": "document"}]),
    ("chip", "Chip Moreno", [{"type": "chip_scanner"}, {"type": "document"}]),
)


def raw_clinic() -> dict[str, Any]:
    return {
        "name": "clinic",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": y}
                for n, (x, y) in enumerate(_DESKS, 1)
            ),
            {"id": "print_corner", "kind": "facility", "name": "Print corner", "x": 4.0, "y": 20.5},
            {"id": "staff_room", "kind": "facility", "name": "Staff room", "x": 11.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "thermometer", "name": "thermometer"},
            {"id": "clipboard", "name": "clipboard"},
            {"id": "chip_scanner", "name": "microchip scanner", "synonyms": ["chip reader"]},
            {"id": "ice_pack", "name": "ice pack", "kind": "personal"},
            {"id": "document", "name": "document", "kind": "personal", "synonyms": ["form"]},
            {"id": "file", "name": "file", "kind": "electronic", "synonyms": ["rota"]},
            {"id": "printout", "name": "printout", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "file",
                "product": "printout",
            }
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "file"}],
                "aliases": ["Manager Rich"] if pid == "rich" else [],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "print_corner",
                "operations": ["print"],
                "guards": ["tomas"],
            },
            {"id": "fridge", "name": "fridge", "location": "staff_room", "guards": ["hal"]},
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "print_corner"},
    }


@functools.cache
def clinic() -> Office:
    return parse_office(raw_clinic(), "clinic")
