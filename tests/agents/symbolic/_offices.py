"""The offices the reader's mechanism tests run on: the default, harbour, and harbour with a
mail room of services whose names are verbs (shred, bind, fax) and people with diacritics."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE, harbour_office
from helpers.yaml_files import raw_yaml


def _mail_room_office() -> Office:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["locations"].append(
        {"id": "mail_room", "kind": "facility", "name": "Mail room", "x": 37.0, "y": 16.0}
    )
    for t in raw["item_types"]:
        if t["id"] == "document":
            t["synonyms"] += ["draft", "thesis"]
    raw["operations"] += [
        {"id": "shred", "name": "shred", "verbs": ["shred"], "input": "document"},
        {"id": "bind", "name": "bind", "verbs": ["bind"], "input": "document"},
        {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "document"},
    ]
    raw["facilities"] += [
        {
            "id": "shredder",
            "name": "shredder",
            "location": "mail_room",
            "operations": ["shred"],
            "guards": ["pat"],
        },
        {
            "id": "binder",
            "name": "binding machine",
            "location": "mail_room",
            "operations": ["bind"],
            "guards": ["pat"],
        },
        {
            "id": "fax_machine",
            "name": "fax machine",
            "synonyms": ["fax"],
            "location": "mail_room",
            "operations": ["fax"],
            "guards": ["art"],
        },
    ]
    for p in raw["people"]:
        if p["id"] == "max":
            p["name"], p["aliases"] = "José Müller", ["José"]
    return parse_office(raw, "harbour with a mail room")


@functools.cache
def office(name: str) -> Office:
    if name == "default":
        return load_office(DEFAULT_FILE)
    if name == "harbour":
        return harbour_office()
    return _mail_room_office()


@functools.cache
def parser(name: str) -> InstructionParser:
    return InstructionParser(office(name))


def tasks_of(name: str, text: str, requester: str) -> list[tuple[str, str | None, str | None, str]]:
    """(kind, item, owner, recipient) of each task, or [] when nothing is to be done yet."""
    frame = parser(name).parse(text, requester)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


Row = tuple[str, str | None, str | None, str]


def understood_tasks(name: str, who: str, text: str) -> list[Row]:
    """``tasks_of`` where the reader must neither ask nor decline (the frame says which if it
    did)."""
    frame = parser(name).parse(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
