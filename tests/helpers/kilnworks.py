"""A ceramics studio's design office for the reader's tests of blind round 14's classes about
who receives and which parts a request has (the round's own office and sentences were never
read). One person is declared by a title with an article ("the Provost"); hole punches are
only ever someone's own, calculators are someone's or kept in the store cupboard for anyone;
a printer prints an agenda file; a legal desk vets reports; reports go out of the studio by
courier or by fax (two send-out services, neither named by a place)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("kit", "Kit Abara", [], [{"type": "hole_punch"}, {"type": "calculator"}]),
    ("oona", "Oona Pike", ["the Provost"], [{"type": "calculator"}]),
    ("sunniva", "Sunniva Holt", [], [{"type": "hole_punch"}]),
    ("teodor", "Teodor Lusk", [], [{"type": "hole_punch"}, {"type": "calculator"}]),
    ("bram", "Bram Okoro", [], [{"type": "calculator"}]),
    ("wen", "Wen Ashby", [], []),
)


def raw_kilnworks() -> dict[str, Any]:
    return {
        "name": "kilnworks",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0), 1)
            ),
            {"id": "print_bay", "kind": "facility", "name": "Print bay", "x": 4.0, "y": 20.5},
            {"id": "legal_room", "kind": "facility", "name": "Legal room", "x": 14.0, "y": 20.5},
            {"id": "post_room", "kind": "facility", "name": "Post room", "x": 24.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "hole_punch", "name": "hole punch", "synonyms": ["punch"]},
            {"id": "calculator", "name": "calculator"},
            {
                "id": "report",
                "name": "report",
                "kind": "personal",
                "signable": True,
                "synonyms": ["glaze report"],
            },
            {
                "id": "agenda",
                "name": "agenda",
                "kind": "electronic",
                "synonyms": ["agenda file", "minutes"],
            },
            {"id": "printout", "name": "printout", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "agenda",
                "product": "printout",
            },
            {
                "id": "vet",
                "name": "legal review",
                "verbs": ["vet", "clear"],
                "input": "report",
                "done": "vetted",
            },
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier"],
                "input": "report",
                "sends_out": True,
                "destination_asked": "the name and address of the place",
            },
            {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "report", "sends_out": True},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "report"}, {"type": "agenda"}],
            }
            for n, (pid, name, aliases, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "print_bay",
                "operations": ["print"],
                "guards": ["bram"],
                "products": ["printout"],
            },
            {
                "id": "legal_desk",
                "name": "legal desk",
                "synonyms": ["legal"],
                "location": "legal_room",
                "operations": ["vet"],
                "guards": ["wen"],
            },
            {
                "id": "post_desk",
                "name": "post desk",
                "location": "post_room",
                "operations": ["courier", "fax"],
                "guards": ["teodor"],
            },
            {
                "id": "store_cupboard",
                "name": "store cupboard",
                "location": "post_room",
                "guards": ["teodor"],
                "supplies": [{"type": "calculator"}],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "print_bay"},
    }


@functools.cache
def kilnworks() -> Office:
    return parse_office(raw_kilnworks(), "kilnworks")
