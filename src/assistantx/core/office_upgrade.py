"""Reading office files of the previous format: what the loader fills in, and says it did.

An office file written before item types had properties and operations were declared still
loads, with one warning per change, and ``assistantx office migrate FILE`` writes the changes
into the file. The previous format differs in three ways:

- no item type says ``signable`` (the paper a person signs or stamps) or ``seals`` (the tool
  that stamps it): the types whose ids were hard-wired for those jobs get the property;
- no ``operations:`` block: each operation a facility lists is taken from the standard
  services (``data/standard_services.yaml``), with the item types it needs when the office
  declares none of that id;
- an item kept at a location where several facilities stand, with no ``facility`` named: the
  one that runs no service there keeps it (a fridge beside a kettle), else the first listed.

The functions work on the raw mapping read from YAML, before validation, so the checks of
``office.parse_office`` then judge the upgraded office like any other.
"""

from __future__ import annotations

import copy
import functools
from pathlib import Path
from typing import Any

import yaml

from assistantx.core.errors import OfficeError

STANDARD_SERVICES = Path(__file__).resolve().parents[1] / "data" / "standard_services.yaml"
# The ids the previous format hard-wired for the paper that is signed and the stamping tool.
_LEGACY_PROPERTY_IDS = {"signable": "document", "seals": "seal"}


def standard() -> dict[str, dict[str, dict[str, Any]]]:
    """The standard services and item types, by section ("operations", "item_types") and id."""
    return _standard()


@functools.cache
def _standard() -> dict[str, dict[str, dict[str, Any]]]:
    raw = yaml.safe_load(STANDARD_SERVICES.read_text(encoding="utf-8"))
    return {
        section: {entry["id"]: entry for entry in raw[section]}
        for section in ("operations", "item_types")
    }


def upgrade(raw: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
    """``raw`` in the current format, and one line per change made (none: it was current)."""
    out = copy.deepcopy(raw)
    notes: list[str] = []
    types = [t for t in out.get("item_types") or [] if isinstance(t, dict)]
    for prop, legacy_id in _LEGACY_PROPERTY_IDS.items():
        if any(t.get(prop) for t in types):
            continue
        for t in types:
            if t.get("id") == legacy_id:
                t[prop] = True
                notes.append(f"item type {legacy_id!r} marked '{prop}: true'")
    if "operations" not in out:
        notes += _standard_services(out)
    notes += _keepers(out)
    return out, notes


def _standard_services(out: dict[str, Any]) -> list[str]:
    standard = _standard()
    facilities = [f for f in out.get("facilities") or [] if isinstance(f, dict)]
    wanted = list(dict.fromkeys(op for f in facilities for op in f.get("operations") or []))
    operations = [
        copy.deepcopy(standard["operations"][op]) for op in wanted if op in standard["operations"]
    ]
    out["operations"] = operations
    notes = (
        [f"no 'operations:' block: the standard {', '.join(o['id'] for o in operations)}"]
        if operations
        else ["no 'operations:' block"]
    )
    types = out.setdefault("item_types", [])
    have = {t.get("id") for t in types if isinstance(t, dict)}
    for op in operations:
        for type_id in (op.get("input"), op.get("product")):
            if type_id and type_id not in have:
                types.append(copy.deepcopy(standard["item_types"][type_id]))
                have.add(type_id)
                notes.append(f"item type {type_id!r} added for the {op['id']} service")
    return notes


def _keepers(out: dict[str, Any]) -> list[str]:
    facilities = [f for f in out.get("facilities") or [] if isinstance(f, dict)]
    runs = {
        o.get("id")
        for o in out.get("operations") or []
        if isinstance(o, dict) and (o.get("input") or o.get("product"))
    }
    notes: list[str] = []
    for person in out.get("people") or []:
        for own in person.get("owns") or [] if isinstance(person, dict) else []:
            if not isinstance(own, dict) or own.get("at") is None or own.get("facility"):
                continue
            here = [f for f in facilities if f.get("location") == own["at"]]
            if len(here) < 2:
                continue
            stores = [f for f in here if not set(f.get("operations") or []) & runs]
            keeper = (stores or here)[0]
            own["facility"] = keeper.get("id")
            notes.append(
                f"{person.get('id')}'s {own.get('type')} at {own['at']!r}: kept by "
                f"{keeper.get('id')!r} (several facilities stand there)"
            )
    return notes


def migrate_file(path: Path, out: Path | None = None) -> list[str]:
    """Write ``path`` in the current format (to ``out``, else in place); the changes made."""
    raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    if not isinstance(raw, dict):
        raise OfficeError(str(path), "file", "must be a mapping with locations, people, ...")
    upgraded, notes = upgrade(raw)
    if notes or out is not None:
        text = yaml.safe_dump(upgraded, sort_keys=False, allow_unicode=True, width=100)
        (out or path).write_text(text, encoding="utf-8")
    return notes
