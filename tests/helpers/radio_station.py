"""A small community radio station for the reader's tests of polite indirect requests and of
operations named by a noun phrase (no blind round's office or sentences were read). A supply
cupboard keeps glue sticks and marker pens; a proofing desk proofreads a script; a legal desk
runs a legal review ("vet") on a contract; a laminator laminates a poster (each comes back
changed); ordinary belongings (a headset, a van key)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("wren", "Wren Okafor", [{"type": "headset"}, {"type": "script"}, {"type": "poster"}]),
    ("basil", "Basil Novak", [{"type": "van_key"}, {"type": "contract"}]),
    ("odile", "Odile Marsh", [{"type": "headset"}, {"type": "script"}]),
    ("teodor", "Teodor Haas", [{"type": "contract"}, {"type": "poster"}]),
    ("linnea", "Linnea Brandt", [{"type": "script"}]),
)


def raw_radio_station() -> dict[str, Any]:
    kept = [
        {"type": "glue_stick", "at": "store_room", "facility": "supply_cupboard"},
        {"type": "marker_pen", "at": "store_room", "facility": "supply_cupboard"},
    ]
    return {
        "name": "radio_station",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0), 1)
            ),
            {"id": "store_room", "kind": "facility", "name": "Store room", "x": 4.0, "y": 20.5},
            {"id": "back_office", "kind": "facility", "name": "Back office", "x": 18.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "headset", "name": "headset"},
            {"id": "van_key", "name": "van key", "synonyms": ["van keys"]},
            {"id": "glue_stick", "name": "glue stick"},
            {"id": "marker_pen", "name": "marker pen"},
            {"id": "script", "name": "script", "kind": "personal", "synonyms": ["show script"]},
            {"id": "contract", "name": "contract", "kind": "personal"},
            {"id": "poster", "name": "poster", "kind": "personal"},
        ],
        "operations": [
            {"id": "proof", "name": "proofread", "verbs": ["proofread"], "input": "script"},
            {"id": "vet", "name": "legal review", "verbs": ["vet"], "input": "contract"},
            {"id": "laminate", "name": "laminate", "verbs": ["laminate"], "input": "poster"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, *(kept if pid == "linnea" else [])],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "supply_cupboard",
                "name": "supply cupboard",
                "location": "store_room",
                "guards": ["linnea"],
            },
            {
                "id": "proof_desk",
                "name": "proofing desk",
                "location": "back_office",
                "operations": ["proof"],
                "guards": ["odile"],
            },
            {
                "id": "legal_desk",
                "name": "legal desk",
                "location": "back_office",
                "operations": ["vet"],
                "guards": ["basil"],
            },
            {
                "id": "laminator",
                "name": "laminator",
                "location": "store_room",
                "operations": ["laminate"],
                "guards": ["teodor"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "store_room"},
    }


@functools.cache
def radio_station() -> Office:
    return parse_office(raw_radio_station(), "radio_station")
