"""A small rowing club's boathouse for the reader's tests of blind round 6's classes: people
with names nobody else uses, ordinary belongings (a headlamp, a stopwatch, a radio), a
charging shelf that charges devices (a treat-shape service on a belonging that is neither food
nor paper), a printer and a desk of signable forms."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("ottilie", "Ottilie Brandt", [{"type": "headlamp"}, {"type": "form"}]),
    ("bram", "Bram Okafor", [{"type": "stopwatch"}, {"type": "headlamp"}, {"type": "form"}]),
    ("kasia", "Kasia Lind", [{"type": "radio"}, {"type": "form"}]),
    ("femi", "Femi Adair", [{"type": "stopwatch"}, {"type": "form"}]),
    ("rune", "Rune Solberg", [{"type": "oar_clamp"}, {"type": "form"}]),
)


def raw_boathouse() -> dict[str, Any]:
    return {
        "name": "boathouse",
        "locations": [
            *(
                {
                    "id": f"bay_{n}",
                    "kind": "workstation",
                    "name": f"Bay {n}",
                    "x": 4.0 * n,
                    "y": 5.0,
                }
                for n in range(1, len(_PEOPLE) + 1)
            ),
            {"id": "tack_room", "kind": "facility", "name": "Tack room", "x": 4.0, "y": 18.0},
        ],
        "item_types": [
            {"id": "headlamp", "name": "headlamp", "synonyms": ["head torch"]},
            {"id": "stopwatch", "name": "stopwatch"},
            {"id": "radio", "name": "radio", "synonyms": ["walkie-talkie"]},
            {"id": "oar_clamp", "name": "oar clamp"},
            {
                "id": "form",
                "name": "form",
                "kind": "personal",
                "signable": True,
                "synonyms": ["waiver", "entry form"],
            },
            {"id": "log", "name": "log", "kind": "electronic", "synonyms": ["spreadsheet"]},
            {"id": "printout", "name": "printout", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "log",
                "product": "printout",
            },
            {
                "id": "charge",
                "name": "charge",
                "verbs": ["charge", "recharge"],
                "input": "headlamp",
            },
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier", "dispatch"],
                "input": "form",
                "sends_out": True,
                "destination_asked": "the name and address of the place",
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"bay_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "log"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "tack_room",
                "operations": ["print"],
                "guards": ["rune"],
            },
            {
                "id": "charging_shelf",
                "name": "charging shelf",
                "location": "tack_room",
                "operations": ["charge"],
                "guards": ["kasia"],
            },
            {
                "id": "dispatch_tray",
                "name": "dispatch tray",
                "location": "tack_room",
                "operations": ["courier"],
                "guards": ["femi"],
            },
        ],
        "groups": [{"id": "crew", "name": "Crew", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "tack_room"},
    }


@functools.cache
def boathouse() -> Office:
    return parse_office(raw_boathouse(), "boathouse")
