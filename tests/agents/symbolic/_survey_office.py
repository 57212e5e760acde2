"""A small office written for the reader's tests and found in no data file: a survey practice
of seven people, two of them named with ordinary words (Bill, Mark), one with an apostrophe in
the surname, a copier, a post tray that couriers documents out, a supply cupboard of tape owned
by nobody, and a kettle. Its sentences in the tests are new; no rule was written for them."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office


def _person(pid: str, name: str, desk: int, owns: list[str], aliases: list[str]) -> dict[str, Any]:
    return {
        "id": pid,
        "name": name,
        "aliases": aliases,
        "location": f"desk_{desk}",
        "handle": f"@{pid}",
        "owns": [{"type": t, "known": True} for t in owns],
    }


def raw() -> dict[str, Any]:
    desks = [
        {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": 4.0 * n, "y": 5.0}
        for n in range(1, 8)
    ]
    return {
        "name": "A small survey practice",
        "locations": [
            *desks,
            {"id": "copy_room", "kind": "facility", "name": "Copy room", "x": 4.0, "y": 12.0},
            {"id": "kitchen", "kind": "facility", "name": "Kitchen", "x": 12.0, "y": 12.0},
            {"id": "studio", "kind": "room", "name": "Studio", "x": 20.0, "y": 12.0},
        ],
        "item_types": [
            {"id": "ruler", "name": "ruler", "synonyms": ["scale rule"]},
            {"id": "calculator", "name": "calculator", "synonyms": ["calc"]},
            {"id": "umbrella", "name": "umbrella", "synonyms": ["brolly"]},
            {"id": "laser", "name": "laser measure", "synonyms": ["distance meter"]},
            {"id": "tape", "name": "tape", "synonyms": ["sticky tape"], "consumable": True},
            {
                "id": "document",
                "name": "document",
                "kind": "personal",
                "signable": True,
                "synonyms": ["invoice", "drawing", "contract", "report"],
            },
            {"id": "file", "name": "electronic file", "kind": "electronic", "synonyms": ["pdf"]},
            {"id": "copy", "name": "photocopy", "kind": "product", "synonyms": ["copies"]},
            {"id": "tea", "name": "tea", "kind": "product", "synonyms": ["cup of tea", "cuppa"]},
        ],
        "people": [
            _person("bill", "Bill Okafor", 1, ["document", "file", "calculator"], []),
            _person(
                "ciaran", "Ciaran O'Keeffe", 2, ["document", "file", "ruler", "laser"], ["Ciaran"]
            ),
            _person("wren", "Wren Halloway", 3, ["document", "file", "umbrella", "ruler"], []),
            _person("tomasz", "Tomasz Lind", 4, ["document", "file", "calculator"], ["Tomasz"]),
            _person("priya", "Priya Nair", 5, ["document", "file"], ["Priya"]),
            _person("hedda", "Hedda Moss", 6, ["document", "file", "laser"], ["Hedda"]),
            _person("mark", "Mark Ellery", 7, ["document", "file", "umbrella"], []),
        ],
        "operations": [
            {
                "id": "copy",
                "name": "copy",
                "verbs": ["copy", "photocopy"],
                "input": "document",
                "product": "copy",
            },
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier", "send out"],
                "input": "document",
                "sends_out": True,
            },
            {"id": "tea", "name": "make tea", "verbs": ["brew"], "product": "tea"},
        ],
        "facilities": [
            {
                "id": "copier",
                "name": "copier",
                "location": "copy_room",
                "operations": ["copy"],
                "guards": ["priya"],
                "products": ["copy"],
            },
            {
                "id": "post_tray",
                "name": "post tray",
                "location": "copy_room",
                "operations": ["courier"],
                "guards": ["priya"],
            },
            {
                "id": "cupboard",
                "name": "supply cupboard",
                "location": "copy_room",
                "guards": ["priya"],
                "supplies": [{"type": "tape"}],
            },
            {
                "id": "kettle",
                "name": "kettle",
                "location": "kitchen",
                "operations": ["tea"],
                "guards": ["hedda"],
                "products": ["tea"],
            },
        ],
        "groups": [
            {
                "id": "all",
                "name": "Everyone",
                "members": ["bill", "ciaran", "wren", "tomasz", "priya", "hedda", "mark"],
            }
        ],
        "robot": {"home": "studio", "speed_mps": 0.5},
    }


@functools.cache
def office() -> Office:
    return parse_office(raw(), "survey practice")


@functools.cache
def parser() -> InstructionParser:
    return InstructionParser(office())


REQUESTER = "tomasz"  # the person who writes the tests' messages


def read(
    text: str,
) -> tuple[list[tuple[str, str | None, str | None, str]], str | None, str | None]:
    """What the reader makes of ``text`` from the requester: its tasks as (kind, item, owner,
    recipient), the question it asks, and its answer in words."""
    frame = parser().parse(text, REQUESTER)
    tasks = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    return tasks, frame.question, frame.decline
