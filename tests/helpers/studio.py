"""A small architecture and photo studio for the tests of composed parts (issue 23, fix14c):
rolls of film kept at a facility (one in the picture archive, one in the fridge, both in the
store room; one on its owner's desk), a darkroom that develops a roll into photo prints (an
operation that makes a product from an item, the ``copy`` kind), a post desk that couriers a
drawing set outside the office (an operation that sends the item out), a signer with a
title, and a stamp two people own."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

import yaml

from assistantx.core.office import Office, parse_office

_DESKS = ((5.0, 6.0), (9.0, 6.0), (13.0, 6.0), (17.0, 6.0), (21.0, 6.0), (25.0, 6.0), (29.0, 6.0))
_KEPT_IN_ARCHIVE = {"type": "film", "at": "store_room", "facility": "picture_archive"}
_KEPT_IN_FRIDGE = {"type": "film", "at": "store_room", "facility": "fridge"}
_PEOPLE: tuple[tuple[str, str, list[dict[str, Any]]], ...] = (
    ("ada", "Ada Lindqvist", [_KEPT_IN_ARCHIVE, {"type": "drawings"}]),
    ("bo", "Bo Farrow", [_KEPT_IN_FRIDGE, {"type": "drawings"}]),
    ("cyrus", "Cyrus Mehta", [{"type": "film"}, {"type": "drawings"}]),
    ("amara", "Amara Osei", [{"type": "drawings"}, {"type": "stamp"}]),
    ("otto", "Otto Brandt", [{"type": "tape_measure"}]),
    ("kai", "Kai Nakamura", [{"type": "tape_measure"}]),
    ("pia", "Pia Holm", [{"type": "stamp"}]),
    ("sven", "Sven Aalto", [{"type": "drawings"}]),
    ("luc", "Luc Perrin", []),
)


def raw_studio() -> dict[str, Any]:
    return {
        "name": "studio",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": y}
                for n, (x, y) in enumerate(_DESKS, 1)
            ),
            {"id": "desk_8", "kind": "workstation", "name": "Desk 8", "x": 33.0, "y": 6.0},
            {"id": "desk_9", "kind": "workstation", "name": "Desk 9", "x": 5.0, "y": 13.0},
            {"id": "store_room", "kind": "facility", "name": "Store room", "x": 11.0, "y": 20.5},
            {"id": "lab", "kind": "facility", "name": "Lab", "x": 23.0, "y": 20.5},
            {"id": "front_desk", "kind": "facility", "name": "Front desk", "x": 37.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "tape_measure", "name": "tape measure"},
            {"id": "film", "name": "roll of film", "kind": "personal", "synonyms": ["film"]},
            {
                "id": "drawings",
                "name": "drawing set",
                "kind": "personal",
                "signable": True,
                "synonyms": ["drawings", "plans"],
            },
            {"id": "stamp", "name": "approval stamp", "seals": True, "synonyms": ["stamp"]},
            {"id": "file", "name": "file", "kind": "electronic"},
            {
                "id": "photo_prints",
                "name": "photo prints",
                "kind": "product",
                "synonyms": ["prints"],
            },
        ],
        "operations": [
            {
                "id": "develop",
                "name": "develop",
                "verbs": ["develop"],
                "input": "film",
                "product": "photo_prints",
            },
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier", "send out"],
                "input": "drawings",
                "sends_out": True,
                "destination_asked": "the name and address of the place",
                "done": "couriered",
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "file"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "picture_archive",
                "name": "picture archive",
                "location": "store_room",
                "guards": ["otto"],
            },
            {"id": "fridge", "name": "fridge", "location": "store_room", "guards": ["kai"]},
            {
                "id": "darkroom",
                "name": "darkroom",
                "location": "lab",
                "operations": ["develop"],
                "guards": ["pia", "sven"],
                "products": ["photo_prints"],
            },
            {
                "id": "post_desk",
                "name": "post desk",
                "location": "front_desk",
                "operations": ["courier"],
                "guards": ["luc"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "front_desk"},
    }


@functools.cache
def studio() -> Office:
    return parse_office(raw_studio(), "studio")


def write_studio(path: Path) -> Path:
    """The studio as an office file, for the command line (``--office``)."""
    path.write_text(yaml.safe_dump(raw_studio(), sort_keys=False), encoding="utf-8")
    return path
