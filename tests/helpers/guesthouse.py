"""A small guesthouse back office for the tests of blind round 14's classes (the round's own
office and sentences were never read). A card encoder makes ordinary door cards from nothing
(no master or all-access variant declared); a tea urn makes tea; a shredder destroys papers
(an operation that consumes its item); a laminator treats a poster (it comes back changed);
ordinary belongings (a step stool, a hole punch) and personal papers (a ledger, a poster)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("wren", "Wren Okafor", [{"type": "step_stool"}, {"type": "ledger"}, {"type": "poster"}]),
    ("basil", "Basil Moreau", [{"type": "hole_punch"}, {"type": "ledger"}]),
    ("ottilie", "Ottilie Brandt", [{"type": "step_stool"}, {"type": "poster"}]),
    ("cosmo", "Cosmo Delacroix", [{"type": "ledger"}]),
    ("juniper", "Juniper Hale", [{"type": "hole_punch"}, {"type": "poster"}]),
)


def raw_guesthouse() -> dict[str, Any]:
    return {
        "name": "guesthouse",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0), 1)
            ),
            {"id": "back_room", "kind": "facility", "name": "Back room", "x": 4.0, "y": 20.5},
            {"id": "pantry", "kind": "facility", "name": "Pantry", "x": 20.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "step_stool", "name": "step stool", "synonyms": ["kick stool"]},
            {"id": "hole_punch", "name": "hole punch"},
            {"id": "ledger", "name": "ledger", "kind": "personal", "synonyms": ["day book"]},
            {"id": "poster", "name": "poster", "kind": "personal"},
            {
                "id": "door_card",
                "name": "door card",
                "kind": "product",
                "synonyms": ["key card", "room card"],
            },
            {"id": "tea", "name": "tea", "kind": "product", "mass": True},
        ],
        "operations": [
            {"id": "encode", "name": "encode", "verbs": ["encode", "cut"], "product": "door_card"},
            {"id": "brew", "name": "brew", "verbs": ["brew"], "product": "tea"},
            {
                "id": "shred",
                "name": "shred",
                "verbs": ["shred"],
                "input": "ledger",
                "consumes": True,
            },
            {"id": "laminate", "name": "laminate", "verbs": ["laminate"], "input": "poster"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": owns,
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "encoder",
                "name": "card encoder",
                "location": "back_room",
                "operations": ["encode"],
                "guards": ["basil"],
                "products": ["door_card"],
            },
            {
                "id": "urn",
                "name": "tea urn",
                "location": "pantry",
                "operations": ["brew"],
                "guards": ["cosmo"],
                "products": ["tea"],
            },
            {
                "id": "shredder",
                "name": "shredder",
                "location": "back_room",
                "operations": ["shred"],
                "guards": ["basil"],
            },
            {
                "id": "laminator",
                "name": "laminator",
                "location": "pantry",
                "operations": ["laminate"],
                "guards": ["cosmo", "juniper"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "back_room"},
    }


@functools.cache
def guesthouse() -> Office:
    return parse_office(raw_guesthouse(), "guesthouse")
