"""A small photo studio for the reader's tests of blind round 14's speech-act classes (the
round's own office and sentences were never read): a proof printer that makes contact sheets
from a shoot file, an ordinary printer, a label printer and a film scanner other people keep,
shared tools (a magnifier, a tape measure, a ruler, a wide lens, a camera), a mug each, and
two folders told apart only by colour."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("lotte", "Lotte Brandt", [{"type": "mug"}, {"type": "tape_measure"}]),
    ("kwame", "Kwame Osei", [{"type": "mug"}, {"type": "magnifier"}, {"type": "wide_lens"}]),
    ("farida", "Farida Haddad", [{"type": "mug"}, {"type": "camera"}, {"type": "wide_lens"}]),
    ("teodor", "Teodor Novak", [{"type": "mug"}, {"type": "tape_measure"}, {"type": "ruler"}]),
    ("maren", "Maren Holt", [{"type": "mug"}, {"type": "blue_folder"}, {"type": "red_folder"}]),
    ("yusuf", "Yusuf Demir", [{"type": "mug"}, {"type": "camera"}, {"type": "negative"}]),
    ("frank", "Frank Ito", [{"type": "mug"}]),
    ("june", "June Adler", [{"type": "mug"}]),
    ("agnes", "Agnes Moreau", [{"type": "mug"}, {"type": "camera"}, {"type": "wide_lens"}]),
)


def raw_studio() -> dict[str, Any]:
    return {
        "name": "studio",
        "locations": [
            *(
                {"id": f"bench_{n}", "kind": "workstation", "name": f"Bench {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0, 29.0, 33.0, 37.0), 1)
            ),
            {"id": "print_room", "kind": "facility", "name": "Print room", "x": 4.0, "y": 20.5},
            {"id": "darkroom", "kind": "facility", "name": "Darkroom", "x": 20.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "magnifier", "name": "magnifier", "synonyms": ["loupe"]},
            {"id": "tape_measure", "name": "tape measure"},
            {"id": "ruler", "name": "ruler"},
            {"id": "wide_lens", "name": "wide lens", "synonyms": ["wide angle lens"]},
            {"id": "camera", "name": "camera"},
            {"id": "mug", "name": "mug", "kind": "personal"},
            {"id": "blue_folder", "name": "blue folder", "kind": "personal"},
            {"id": "red_folder", "name": "red folder", "kind": "personal"},
            {"id": "negative", "name": "negative strip", "kind": "personal"},
            {
                "id": "shoot_file",
                "name": "shoot file",
                "kind": "electronic",
                "synonyms": ["shoot", "photo file"],
            },
            {"id": "printout", "name": "printout", "kind": "product"},
            {
                "id": "contact_sheet",
                "name": "contact sheet",
                "kind": "product",
                "synonyms": ["proof sheet", "contacts"],
            },
            {"id": "sticker", "name": "sticker label", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "shoot_file",
                "product": "printout",
            },
            {
                "id": "proof",
                "name": "proof",
                "verbs": ["proof"],
                "input": "shoot_file",
                "product": "contact_sheet",
            },
            {"id": "label", "name": "label", "verbs": ["label"], "product": "sticker"},
            {"id": "scan", "name": "scan", "verbs": ["scan"], "input": "negative"},
            {"id": "develop", "name": "develop", "verbs": ["develop", "run"], "input": "negative"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"bench_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "shoot_file"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "print_room",
                "operations": ["print", "proof"],
                "guards": ["teodor"],
                "products": ["printout", "contact_sheet"],
            },
            {
                "id": "label_printer",
                "name": "label printer",
                "location": "print_room",
                "operations": ["label"],
                "guards": ["teodor"],
                "products": ["sticker"],
            },
            {
                "id": "scanner",
                "name": "film scanner",
                "synonyms": ["scanner"],
                "location": "darkroom",
                "operations": ["scan", "develop"],
                "guards": ["yusuf"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "print_room"},
    }


@functools.cache
def studio() -> Office:
    return parse_office(raw_studio(), "studio")
