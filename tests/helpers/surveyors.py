"""A land surveyors' practice for the reader's tests of blind round 7's classes (the round's
law firm and sentences were never read): two partners own the chartered stamp (an owned
tool that stamps the practice's papers), one copier in the plan room copies, scans to PDF
and binds (three operations of one machine, two of one shape), a post desk couriers and
faxes papers out of the office, and a colleague is called Bill (a word of the post desk's
trade). Its signable paper is a "plan"; leases, affidavits and wills are papers it never
lists."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("ines", "Ines Varga", ["stamp", "plan", "tape"]),
    ("tobias", "Tobias Rehn", ["stamp", "plan"]),
    ("bill", "Bill Osei", ["plan", "tripod"]),
    ("noor", "Noor Haddad", ["plan", "level"]),
    ("callum", "Callum Price", ["plan", "tripod", "tape"]),
    ("otto", "Otto Lindgren", ["plan", "level"]),
)


def raw_surveyors() -> dict[str, Any]:
    return {
        "name": "surveyors",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": 4.0 * n}
                | {"y": 6.0}
                for n in range(1, len(_PEOPLE) + 1)
            ),
            {"id": "plan_room", "kind": "facility", "name": "Plan room", "x": 4.0, "y": 18.0},
            {"id": "post_room", "kind": "facility", "name": "Post room", "x": 16.0, "y": 18.0},
        ],
        "item_types": [
            {"id": "tape", "name": "measuring tape", "synonyms": ["tape measure"]},
            {"id": "level", "name": "spirit level", "synonyms": ["level"]},
            {"id": "tripod", "name": "tripod"},
            {
                "id": "stamp",
                "name": "chartered stamp",
                "seals": True,
                "synonyms": ["stamp", "embosser", "practice seal"],
            },
            {
                "id": "plan",
                "name": "plan",
                "kind": "personal",
                "signable": True,
                "synonyms": ["survey plan", "contract", "certificate"],
            },
            {
                "id": "drawing",
                "name": "drawing file",
                "kind": "electronic",
                "synonyms": ["drawing", "draft", "cad file"],
            },
            {"id": "pdf", "name": "PDF", "kind": "electronic", "synonyms": ["pdf file"]},
            {"id": "plot", "name": "plot", "kind": "product", "synonyms": ["printout"]},
            {"id": "copy", "name": "copy", "kind": "product", "synonyms": ["photocopy"]},
        ],
        "operations": [
            {
                "id": "plot",
                "name": "print",
                "verbs": ["print", "plot"],
                "input": "drawing",
                "product": "plot",
            },
            {
                "id": "copy",
                "name": "copy",
                "verbs": ["copy", "photocopy"],
                "input": "plan",
                "product": "copy",
            },
            {
                "id": "scan",
                "name": "scan",
                "verbs": ["scan", "digitise"],
                "input": "plan",
                "product": "pdf",
                "done": "scanned to PDF",
            },
            {"id": "bind", "name": "bind", "verbs": ["bind"], "input": "plan"},
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier"],
                "input": "plan",
                "sends_out": True,
            },
            {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "plan", "sends_out": True},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*({"type": t} for t in owns), {"type": "drawing"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "copier",
                "name": "copier",
                "synonyms": ["photocopier"],
                "location": "plan_room",
                "operations": ["copy", "scan", "bind"],
                "guards": ["otto"],
            },
            {
                "id": "plotter",
                "name": "plotter",
                "location": "plan_room",
                "operations": ["plot"],
                "guards": ["otto"],
            },
            {
                "id": "post_desk",
                "name": "post desk",
                "location": "post_room",
                "operations": ["courier", "fax"],
                "guards": ["noor"],
            },
        ],
        "groups": [{"id": "practice", "name": "Practice", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "plan_room"},
    }


@functools.cache
def surveyors() -> Office:
    return parse_office(raw_surveyors(), "surveyors")
