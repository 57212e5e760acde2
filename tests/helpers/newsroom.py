"""A small regional newsroom for the reader's tests of blind round 16's classes (the round's
own office and sentences were never read). A legal desk gives a page proof a "legal read"
(it comes back); a dispatch desk sends proofs out with a courier to a place outside the
office (asked "which printing works it should go to"); a print room prints a file; a
stationery cupboard keeps reporter's notebooks and pens for anyone; a kitchen makes coffee
and tea (plain only); a managing editor stamps with the desk stamp; a post room takes what is
left for the post. ``newsroom()`` is the office; ``raw_newsroom()`` its dictionary, for a test
that needs a variant."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("ines", "Ines Varga", [{"type": "page_proof"}, {"type": "lanyard"}]),
    ("tomas", "Tomas Reyes", [{"type": "page_proof"}, {"type": "desk_stamp"}]),
    ("femi", "Femi Adeyemi", [{"type": "page_proof"}]),
    ("marta", "Marta Lindqvist", [{"type": "page_proof"}, {"type": "lanyard"}]),
    ("oskar", "Oskar Brandt", [{"type": "page_proof"}]),
    ("hana", "Hana Sato", []),
)


def raw_newsroom(*, style_desk: bool = False) -> dict[str, Any]:
    """The office's dictionary; ``style_desk``: a subs desk also gives proofs a "style read"
    (two operations then share the head noun "read" of their names)."""
    raw = _raw()
    if style_desk:
        raw["operations"].append(
            {"id": "subedit", "name": "style read", "verbs": ["subedit"], "input": "page_proof"}
        )
        raw["facilities"].append(
            {
                "id": "subs_desk",
                "name": "subs desk",
                "location": "back_office",
                "operations": ["subedit"],
                "guards": ["femi"],
            }
        )
    return raw


def _raw() -> dict[str, Any]:
    return {
        "name": "newsroom",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0), 1)
            ),
            {"id": "back_office", "kind": "facility", "name": "Back office", "x": 6.0, "y": 20.5},
            {"id": "post_room", "kind": "facility", "name": "Post room", "x": 14.0, "y": 20.5},
            {"id": "kitchen", "kind": "facility", "name": "Kitchen", "x": 22.0, "y": 20.5},
        ],
        "item_types": [
            {
                "id": "page_proof",
                "name": "page proof",
                "kind": "personal",
                "signable": True,
                "synonyms": ["proof"],
            },
            {"id": "lanyard", "name": "lanyard"},
            {"id": "desk_stamp", "name": "desk stamp", "seals": True},
            {"id": "notebook", "name": "reporter's notebook", "consumable": True},
            {"id": "pen", "name": "pen", "consumable": True},
            {"id": "agenda", "name": "agenda", "kind": "electronic"},
            {"id": "printout", "name": "printout", "kind": "product"},
            {"id": "coffee", "name": "coffee", "kind": "product"},
            {"id": "tea", "name": "tea", "kind": "product"},
        ],
        "operations": [
            {"id": "vet", "name": "legal read", "verbs": ["vet"], "input": "page_proof"},
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier"],
                "input": "page_proof",
                "sends_out": True,
                "destination_asked": "which printing works it should go to",
                "done": "sent with the courier",
            },
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "agenda",
                "product": "printout",
            },
            {"id": "brew", "name": "make coffee", "verbs": ["brew"], "product": "coffee"},
            {"id": "steep", "name": "make tea", "verbs": ["steep"], "product": "tea"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "agenda"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "legal_desk",
                "name": "legal desk",
                "location": "back_office",
                "operations": ["vet"],
                "guards": ["oskar"],
            },
            {
                "id": "dispatch",
                "name": "dispatch desk",
                "location": "post_room",
                "operations": ["courier"],
                "guards": ["hana"],
            },
            {
                "id": "post_room_tray",
                "name": "post room",
                "location": "post_room",
                "guards": ["hana"],
            },
            {
                "id": "print_room",
                "name": "print room",
                "location": "back_office",
                "operations": ["print"],
                "guards": ["oskar"],
                "products": ["printout"],
            },
            {
                "id": "cupboard",
                "name": "stationery cupboard",
                "synonyms": ["cupboard"],
                "location": "back_office",
                "guards": ["oskar"],
                "supplies": [{"type": "notebook"}, {"type": "pen"}],
            },
            {
                "id": "kitchen_counter",
                "name": "kitchen counter",
                "location": "kitchen",
                "operations": ["brew", "steep"],
                "guards": ["marta"],
                "products": ["coffee", "tea"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "back_office"},
    }


@functools.cache
def newsroom() -> Office:
    return parse_office(raw_newsroom(), "newsroom")


@functools.cache
def newsroom_with_style_desk() -> Office:
    return parse_office(raw_newsroom(style_desk=True), "newsroom-style-desk")
