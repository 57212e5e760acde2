"""A small county records archive for the reader's tests of blind round 13's classes (the
round's own office and sentences were never read). An ordinary printer prints a document file;
a second operation on the same file has a display name that reads like a verb phrase ("print
box labels") though its only verb is "tag", at a tag printer other people guard; a badge
press makes visitor passes from nothing; a reel reader digitises a glass slide into an
electronic scan; a mounting press mounts a chart (the chart comes back changed); ordinary
belongings (a step ladder, a tape gun)."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE = (
    ("ines", "Ines Varga", [{"type": "tape_gun"}, {"type": "chart"}, {"type": "slide"}]),
    ("tobias", "Tobias Reed", [{"type": "step_ladder"}, {"type": "chart"}]),
    ("priya", "Priya Nair", [{"type": "tape_gun"}, {"type": "slide"}]),
    ("jonas", "Jonas Kell", [{"type": "chart"}]),
    ("mira", "Mira Sato", [{"type": "slide"}]),
    ("oskar", "Oskar Lind", [{"type": "chart"}]),
)


def raw_archive() -> dict[str, Any]:
    return {
        "name": "archive",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate((5.0, 9.0, 13.0, 17.0, 21.0, 25.0), 1)
            ),
            {"id": "copy_room", "kind": "facility", "name": "Copy room", "x": 4.0, "y": 20.5},
            {"id": "stack_room", "kind": "facility", "name": "Stack room", "x": 20.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "step_ladder", "name": "step ladder", "synonyms": ["kick step"]},
            {"id": "tape_gun", "name": "tape gun"},
            {"id": "chart", "name": "chart", "kind": "personal", "synonyms": ["map sheet"]},
            {"id": "slide", "name": "glass slide", "kind": "personal", "synonyms": ["slide"]},
            {
                "id": "doc_file",
                "name": "document file",
                "kind": "electronic",
                "synonyms": ["document", "box list", "pdf"],
            },
            {"id": "printout", "name": "printout", "kind": "product"},
            {
                "id": "box_label",
                "name": "box labels",
                "kind": "product",
                "synonyms": ["box label"],
            },
            {
                "id": "pass_card",
                "name": "visitor pass",
                "kind": "product",
                "synonyms": ["pass card"],
            },
            {
                "id": "slide_scan",
                "name": "slide scan",
                "kind": "electronic",
                "synonyms": ["slide image"],
            },
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "doc_file",
                "product": "printout",
            },
            {
                "id": "tag",
                "name": "print box labels",
                "verbs": ["tag"],
                "input": "doc_file",
                "product": "box_label",
            },
            {"id": "badge", "name": "issue passes", "verbs": ["issue"], "product": "pass_card"},
            {
                "id": "digitise",
                "name": "digitise",
                "verbs": ["scan", "digitise"],
                "input": "slide",
                "product": "slide_scan",
            },
            {"id": "mount", "name": "mount", "verbs": ["mount", "backboard"], "input": "chart"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": [*owns, {"type": "doc_file"}],
            }
            for n, (pid, name, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "copy_room",
                "operations": ["print"],
                "guards": ["jonas"],
                "products": ["printout"],
            },
            {
                "id": "tag_printer",
                "name": "tag printer",
                "location": "stack_room",
                "operations": ["tag"],
                "guards": ["mira", "oskar"],
                "products": ["box_label"],
            },
            {
                "id": "badge_press",
                "name": "badge press",
                "location": "copy_room",
                "operations": ["badge"],
                "guards": ["jonas"],
                "products": ["pass_card"],
            },
            {
                "id": "reel_reader",
                "name": "reel reader",
                "location": "stack_room",
                "operations": ["digitise"],
                "guards": ["mira"],
            },
            {
                "id": "mount_press",
                "name": "mounting press",
                "location": "stack_room",
                "operations": ["mount"],
                "guards": ["oskar", "tobias"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "copy_room"},
    }


@functools.cache
def archive() -> Office:
    return parse_office(raw_archive(), "archive")
