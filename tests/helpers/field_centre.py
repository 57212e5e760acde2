"""A field studies centre staff base for the tests of blind round 17's classes (the round's own
office and sentences were never read). Two people share the first name Robin and are told apart
by an alias with an initial ("Robin B", "Robin O"); the deputy head has role aliases ("the
Deputy Head", "the deputy"); a reprographics room goes by "repro", and a colleague sits there;
a kit store keeps hi-vis vests for anyone (a supply); papers to sign (consent forms), a personal
banner, an electronic file that the print room renders as a printout, and ordinary belongings
(board markers, scissors, hole punches, a torch)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

# (id, name, aliases, location, owned types)
_PEOPLE: tuple[tuple[str, str, list[str], str, list[str]], ...] = (
    ("bea", "Bea Lindgren", [], "desk_1", ["hole_punch", "consent_form", "file"]),
    ("robin_b", "Robin Baptiste", ["Robin B"], "desk_2", ["scissors", "file"]),
    ("robin_o", "Robin Okonkwo", ["Robin O"], "desk_3", ["board_marker", "scissors", "file"]),
    ("tomas", "Tomás Ibarra", [], "desk_4", ["board_marker", "hole_punch", "file", "torch"]),
    ("nkechi", "Nkechi Adeyemi", [], "desk_5", ["consent_form", "file"]),
    ("linh", "Linh Vo", [], "desk_6", ["file"]),
    (
        "marguerite",
        "Marguerite Sallow",
        ["the Deputy Head", "the deputy"],
        "desk_7",
        ["consent_form", "file"],
    ),
    ("hattie", "Hattie Quill", [], "repro_room", ["hole_punch"]),
    ("fenella", "Fenella Hart", [], "desk_8", ["scissors", "board_marker"]),
    ("otto", "Otto Brisk", [], "desk_9", ["banner"]),
)


def raw_field_centre() -> dict[str, Any]:
    return {
        "name": "field_centre",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0, 29.0, 33.0, 37.0), 1)
            ),
            {"id": "repro_room", "kind": "facility", "name": "Repro room", "x": 4.0, "y": 20.5},
            {"id": "kit_room", "kind": "facility", "name": "Kit room", "x": 20.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "board_marker", "name": "board marker", "synonyms": ["board pen"]},
            {"id": "scissors", "name": "scissors", "synonyms": ["pair of scissors"]},
            {"id": "hole_punch", "name": "hole punch"},
            {"id": "torch", "name": "torch", "synonyms": ["flashlight"]},
            {"id": "hi_vis", "name": "hi-vis vest", "synonyms": ["hi-vis", "high-vis vest"]},
            {
                "id": "consent_form",
                "name": "consent form",
                "kind": "personal",
                "signable": True,
                "synonyms": ["permission slip"],
            },
            {"id": "banner", "name": "banner", "kind": "personal"},
            {
                "id": "file",
                "name": "electronic file",
                "kind": "electronic",
                "synonyms": ["file", "pdf", "lesson plan", "worksheet"],
            },
            {"id": "printout", "name": "printout", "kind": "product", "synonyms": ["hard copy"]},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "file",
                "product": "printout",
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": location,
                "handle": f"@{pid}",
                "owns": [{"type": t} for t in owns],
            }
            for pid, name, aliases, location, owns in _PEOPLE
        ],
        "facilities": [
            {
                "id": "reprographics",
                "name": "reprographics room",
                "synonyms": ["repro"],
                "location": "repro_room",
                "operations": ["print"],
                "guards": ["hattie"],
                "products": ["printout"],
            },
            {
                "id": "kit_store",
                "name": "kit store",
                "location": "kit_room",
                "guards": ["linh"],
                "supplies": [{"type": "hi_vis"}],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "kit_room"},
    }


@functools.cache
def field_centre() -> Office:
    return parse_office(raw_field_centre(), "field_centre")
