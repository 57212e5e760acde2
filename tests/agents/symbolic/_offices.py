"""The offices the reader's mechanism tests run on: the default, harbour, and harbour with a
mail room of services whose names are verbs (shred, bind, fax) and people with diacritics."""

from __future__ import annotations

import copy
import functools
from pathlib import Path
from typing import Any

import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office

ROOT = Path(__file__).resolve().parents[3]
DEFAULT = ROOT / "dataset" / "office.yaml"
HARBOUR = ROOT / "dataset" / "offices" / "harbour" / "office.yaml"


def _mail_room_office() -> Office:
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(HARBOUR.read_text(encoding="utf-8")))
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
        return load_office(DEFAULT)
    if name == "harbour":
        return load_office(HARBOUR)
    return _mail_room_office()


@functools.cache
def parser(name: str) -> InstructionParser:
    return InstructionParser(office(name))


def tasks_of(name: str, text: str, requester: str) -> list[tuple[str, str | None, str | None, str]]:
    """(kind, item, owner, recipient) of each task, or [] when nothing is to be done yet."""
    frame = parser(name).parse(text, requester)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
