"""A small book bindery and reading room for the reader's tests of blind round 13's classes
(the round's own office and sentences were never read). Several colleagues' given names are
also English words (Penny, Ivy, Robin, Page), some carry diacritics (Thảo, Łukasz, Zoë, Jürgen);
the bindery rebinds a worn book and prints a flyer from a file; a staff fridge keeps people's
lunches; a kitchen makes coffee and water; condition reports are signed by a colleague."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_DESKS = tuple((5.0 + 4 * n, 6.0) for n in range(8))
_PEOPLE: tuple[tuple[str, str, list[str], list[dict[str, Any]]], ...] = (
    ("penny", "Penny Castellanos", [], [{"type": "puppet"}, {"type": "report"}]),
    ("ivy", "Ivy Marchetti", ["Ives"], [{"type": "kick_stool"}]),
    ("robin", "Robin Okonkwo", [], [{"type": "report"}]),
    ("page", "Oksana Page", [], [{"type": "kick_stool"}, {"type": "report"}]),
    ("thao", "Thảo Nguyễn", [], [{"type": "report"}]),
    ("lukasz", "Łukasz Wróbel", ["Luke"], [{"type": "bone_folder"}]),
    ("zoe", "Zoë Brandt", [], [{"type": "bone_folder"}, {"type": "report"}]),
    (
        "jurgen",
        "Jürgen Falk",
        [],
        [{"type": "lunch", "at": "kitchen", "facility": "fridge"}, {"type": "report"}],
    ),
)


def raw_bindery() -> dict[str, Any]:
    return {
        "name": "bindery",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": y}
                for n, (x, y) in enumerate(_DESKS, 1)
            ),
            {"id": "workroom", "kind": "facility", "name": "Workroom", "x": 4.0, "y": 20.5},
            {"id": "kitchen", "kind": "facility", "name": "Kitchen", "x": 11.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "puppet", "name": "puppet", "synonyms": ["hand puppet"]},
            {"id": "kick_stool", "name": "kick stool", "synonyms": ["step stool"]},
            {"id": "bone_folder", "name": "bone folder"},
            {"id": "lunch", "name": "lunch box", "synonyms": ["lunchbox"]},
            {
                "id": "report",
                "name": "condition report",
                "kind": "personal",
                "signable": True,
            },
            {"id": "book", "name": "worn book", "synonyms": ["damaged book"]},
            {"id": "flyer_file", "name": "flyer file", "kind": "electronic"},
            {"id": "brochure", "name": "brochure", "kind": "product", "synonyms": ["flyer"]},
            {"id": "rebound", "name": "rebound book", "kind": "product"},
            {"id": "coffee", "name": "coffee", "kind": "product"},
            {"id": "water", "name": "water", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "flyer_file",
                "product": "brochure",
            },
            {
                "id": "rebind",
                "name": "rebind",
                "verbs": ["rebind"],
                "input": "book",
                "product": "rebound",
            },
            {"id": "brew", "name": "make coffee", "verbs": ["brew"], "product": "coffee"},
            {"id": "pour", "name": "pour water", "verbs": ["pour"], "product": "water"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "flyer_file"}, {"type": "book"}],
            }
            for n, (pid, name, aliases, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "workroom",
                "operations": ["print"],
                "guards": ["page"],
                "products": ["brochure"],
            },
            {
                "id": "press",
                "name": "bindery press",
                "location": "workroom",
                "operations": ["rebind"],
                "guards": ["page"],
                "products": ["rebound"],
            },
            {
                "id": "fridge",
                "name": "staff fridge",
                "synonyms": ["fridge"],
                "location": "kitchen",
                "guards": ["robin"],
            },
            {
                "id": "coffee_machine",
                "name": "coffee machine",
                "location": "kitchen",
                "operations": ["brew"],
                "products": ["coffee"],
                "guards": ["robin"],
            },
            {
                "id": "water_cooler",
                "name": "water cooler",
                "location": "kitchen",
                "operations": ["pour"],
                "products": ["water"],
                "guards": ["robin"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "workroom"},
    }


@functools.cache
def bindery() -> Office:
    return parse_office(raw_bindery(), "bindery")
