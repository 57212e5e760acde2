"""A small letterpress and signage studio for the reader's tests of blind round 10's classes
(the round's own office and sentences were never read). Two operations of one shape work on
a file: the printer prints it, the engraver engraves it (an "etched plate", also called "a
brass print"); a paper store keeps card stock for anyone (three sheets left) and cotton
string; a post desk where Ravi works sends papers out; ordinary belongings (a bone folder, also
called a creaser), and proofs that a colleague signs."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_DESKS = ((5.0, 6.0), (9.0, 6.0), (13.0, 6.0), (17.0, 6.0), (21.0, 6.0), (25.0, 6.0))
_PEOPLE = (
    ("edda", "Edda Lund", [{"type": "bone_folder"}, {"type": "proof"}]),
    ("kofi", "Kofi Mensah", [{"type": "bone_folder"}, {"type": "proof"}]),
    ("lena", "Lena Ortiz", [{"type": "loupe"}, {"type": "proof"}]),
    ("ravi", "Ravi Batra", [{"type": "proof"}]),
    ("noor", "Noor Haddad", [{"type": "loupe"}, {"type": "proof"}]),
    ("ugo", "Ugo Ferri", [{"type": "proof"}]),
)


def raw_printshop() -> dict[str, Any]:
    return {
        "name": "printshop",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": y}
                for n, (x, y) in enumerate(_DESKS, 1)
            ),
            {"id": "press_room", "kind": "facility", "name": "Press room", "x": 4.0, "y": 20.5},
            {"id": "front_desk", "kind": "facility", "name": "Front desk", "x": 11.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "bone_folder", "name": "bone folder", "synonyms": ["creaser"]},
            {"id": "loupe", "name": "loupe", "synonyms": ["magnifier"]},
            {
                "id": "proof",
                "name": "proof",
                "kind": "personal",
                "signable": True,
                "synonyms": ["proof sheet", "layout"],
            },
            {"id": "artwork", "name": "artwork file", "kind": "electronic", "synonyms": ["svg"]},
            {"id": "printout", "name": "printout", "kind": "product", "synonyms": ["print"]},
            {
                "id": "plate",
                "name": "etched plate",
                "kind": "product",
                "synonyms": ["brass print", "engraving"],
            },
            {"id": "card_stock", "name": "card stock", "consumable": True, "synonyms": ["card"]},
            {"id": "string", "name": "cotton string", "consumable": True},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "artwork",
                "product": "printout",
            },
            {
                "id": "engrave",
                "name": "engrave",
                "verbs": ["engrave", "etch"],
                "input": "artwork",
                "product": "plate",
            },
            {
                "id": "post",
                "name": "post",
                "verbs": ["post", "mail"],
                "input": "proof",
                "sends_out": True,
            },
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": "front_desk" if pid == "ravi" else f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "artwork"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "press_room",
                "operations": ["print"],
                "guards": ["ugo"],
                "products": ["printout"],
            },
            {
                "id": "engraver",
                "name": "engraver",
                "synonyms": ["etching machine"],
                "location": "press_room",
                "operations": ["engrave"],
                "guards": ["ugo"],
                "products": ["plate"],
            },
            {
                "id": "paper_store",
                "name": "paper store",
                "location": "press_room",
                "guards": ["ugo"],
                "supplies": [{"type": "card_stock", "count": 3}, {"type": "string"}],
            },
            {
                "id": "post_desk",
                "name": "post desk",
                "synonyms": ["mailroom"],
                "location": "front_desk",
                "operations": ["post"],
                "guards": ["ravi"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "press_room"},
    }


@functools.cache
def printshop() -> Office:
    return parse_office(raw_printshop(), "printshop")
