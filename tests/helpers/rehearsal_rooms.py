"""Two offices whose electronic file type is not called ``file``, for the tests of issue 23's
dataset tools (an outside writer's new office crashed ``dataset generate``).

- ``rehearsal_rooms``: a theatre's rehearsal rooms. Everyone's electronic ``script`` (the
  office's only file-like type) is made up into a rehearsal script pack at the photocopier,
  whose keepers are Ines and Tomas (Ines also asks for packs: a requester who is a keeper);
  the green-room urn makes tea; a prop cupboard keeps gaffer tape for anyone; contracts are
  signed by a colleague.
- ``drafting_studio``: an architects' studio. Everyone's ``drawing`` (the electronic type) is
  plotted at the plotter, kept by Mira and Oskar; there is no other file type either.
"""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_REHEARSAL_PEOPLE: tuple[tuple[str, str, list[dict[str, Any]]], ...] = (
    ("ines", "Ines Carvalho", [{"type": "torch"}, {"type": "contract"}]),
    ("tomas", "Tomas Weller", [{"type": "contract"}]),
    ("priya", "Priya Raman", [{"type": "torch"}, {"type": "contract"}]),
    ("bruno", "Bruno Aalto", [{"type": "stopwatch"}, {"type": "contract"}]),
    ("hedda", "Hedda Moreau", [{"type": "stopwatch"}, {"type": "contract"}]),
    ("kwesi", "Kwesi Boateng", [{"type": "contract"}]),
)


def raw_rehearsal_rooms() -> dict[str, Any]:
    return {
        "name": "rehearsal_rooms",
        "locations": [
            *(
                {
                    "id": f"desk_{n}",
                    "kind": "workstation",
                    "name": f"Desk {n}",
                    "x": 4.0 * n,
                    "y": 5.0,
                }
                for n in range(1, len(_REHEARSAL_PEOPLE) + 1)
            ),
            {"id": "copy_corner", "kind": "facility", "name": "Copy corner", "x": 6.0, "y": 18.0},
            {"id": "green_room", "kind": "facility", "name": "Green room", "x": 18.0, "y": 18.0},
        ],
        "item_types": [
            {"id": "torch", "name": "torch", "synonyms": ["flashlight"]},
            {"id": "stopwatch", "name": "stopwatch"},
            {"id": "gaffer_tape", "name": "gaffer tape", "consumable": True, "mass": True},
            {
                "id": "contract",
                "name": "contract",
                "kind": "personal",
                "signable": True,
            },
            {"id": "script", "name": "script", "kind": "electronic"},
            {
                "id": "script_pack",
                "name": "rehearsal script pack",
                "kind": "product",
                "synonyms": ["script pack"],
            },
            {"id": "tea", "name": "tea", "kind": "product"},
        ],
        "operations": [
            {
                "id": "make_pack",
                "name": "make up",
                "verbs": ["make up"],
                "input": "script",
                "product": "script_pack",
            },
            {"id": "brew", "name": "make tea", "verbs": ["brew"], "product": "tea"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "script"}],
            }
            for n, (pid, name, owns) in enumerate(_REHEARSAL_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "photocopier",
                "name": "photocopier",
                "location": "copy_corner",
                "operations": ["make_pack"],
                "guards": ["ines", "tomas"],
                "products": ["script_pack"],
            },
            {
                "id": "urn",
                "name": "tea urn",
                "location": "green_room",
                "operations": ["brew"],
                "guards": ["hedda"],
                "products": ["tea"],
            },
            {
                "id": "prop_cupboard",
                "name": "prop cupboard",
                "location": "green_room",
                "guards": ["hedda"],
                "supplies": [{"type": "gaffer_tape"}],
            },
        ],
        "groups": [
            {"id": "company", "name": "Company", "members": [p[0] for p in _REHEARSAL_PEOPLE]}
        ],
        "robot": {"home": "copy_corner"},
    }


@functools.cache
def rehearsal_rooms() -> Office:
    return parse_office(raw_rehearsal_rooms(), "rehearsal_rooms")


_DRAFTING_PEOPLE: tuple[tuple[str, str], ...] = (
    ("mira", "Mira Castell"),
    ("oskar", "Oskar Lind"),
    ("femi", "Femi Adeyemi"),
    ("greta", "Greta Holm"),
    ("yusuf", "Yusuf Demir"),
)


def raw_drafting_studio() -> dict[str, Any]:
    return {
        "name": "drafting_studio",
        "locations": [
            *(
                {
                    "id": f"desk_{n}",
                    "kind": "workstation",
                    "name": f"Desk {n}",
                    "x": 5.0 * n,
                    "y": 4.0,
                }
                for n in range(1, len(_DRAFTING_PEOPLE) + 1)
            ),
            {"id": "plot_room", "kind": "facility", "name": "Plot room", "x": 12.0, "y": 16.0},
        ],
        "item_types": [
            {"id": "scale_rule", "name": "scale rule"},
            {"id": "drawing", "name": "drawing", "kind": "electronic", "synonyms": ["cad file"]},
            {"id": "plot", "name": "plot", "kind": "product", "synonyms": ["large print"]},
        ],
        "operations": [
            {
                "id": "plot",
                "name": "plot",
                "verbs": ["plot"],
                "input": "drawing",
                "product": "plot",
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [{"type": "scale_rule"}, {"type": "drawing"}],
            }
            for n, (pid, name) in enumerate(_DRAFTING_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "plotter",
                "name": "plotter",
                "location": "plot_room",
                "operations": ["plot"],
                "guards": ["mira", "oskar"],
                "products": ["plot"],
            },
        ],
        "groups": [{"id": "studio", "name": "Studio", "members": [p[0] for p in _DRAFTING_PEOPLE]}],
        "robot": {"home": "plot_room"},
    }


@functools.cache
def drafting_studio() -> Office:
    return parse_office(raw_drafting_studio(), "drafting_studio")
