"""The dataset's offices with some colleagues renamed, for the reader's tests of names: a
name that is also a word of the office's English ("Skip", "Bin"), or one colleague's given
name that is another's family name ("Morgan")."""

from __future__ import annotations

import copy
import functools
from pathlib import Path
from typing import Any

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

# person id → (full name, aliases)
Renames = tuple[tuple[str, str, tuple[str, ...]], ...]


@functools.cache
def _raw(path: Path) -> dict[str, Any]:
    loaded: dict[str, Any] = raw_yaml(path)
    return loaded


def renamed(path: Path, renames: Renames, label: str) -> Office:
    """The office file at ``path`` with each (id, name, aliases) of ``renames`` so called."""
    raw = copy.deepcopy(_raw(path))
    by_id = {person_id: (name, aliases) for person_id, name, aliases in renames}
    for p in raw["people"]:
        if p["id"] in by_id:
            p["name"], aliases = by_id[p["id"]]
            p["aliases"] = list(aliases)
    return parse_office(raw, label)


@functools.cache
def harbour_with_skip() -> Office:
    """Harbour, Bill Ferreira now Skip Larsen, called "Skip" (id ``bill`` kept)."""
    return renamed(HARBOUR_FILE, (("bill", "Skip Larsen", ("Skip",)),), "harbour with a Skip")


@functools.cache
def default_with_bin() -> Office:
    """The default office, Dang Hao now Dang Bin, called "Bin" (family name first, as the
    office writes its names; id ``dang`` kept)."""
    return renamed(DEFAULT_FILE, (("dang", "Dang Bin", ("Bin",)),), "default with a Bin")


@functools.cache
def harbour_with_morgans() -> Office:
    """Harbour, Bill Ferreira now Morgan Tallis (called "Morgan") and Jack Moreau now Priya
    Morgan (called "Inspector Morgan"); ids ``bill`` and ``jack`` kept."""
    return renamed(
        HARBOUR_FILE,
        (
            ("bill", "Morgan Tallis", ("Morgan",)),
            ("jack", "Priya Morgan", ("Inspector Morgan",)),
        ),
        "harbour with two Morgans",
    )


@functools.cache
def harbour_with_grants() -> Office:
    """Harbour, Ray Castillo now Grant Osei (called "Grant") and Faith Oduya now Lucía Grant
    (called "Lucía"); ids ``ray`` and ``faith`` kept."""
    return renamed(
        HARBOUR_FILE,
        (("ray", "Grant Osei", ("Grant",)), ("faith", "Lucía Grant", ("Lucía",))),
        "harbour with two Grants",
    )


@functools.cache
def default_with_two_taos() -> Office:
    """The default office (family name first), Dang Hao now Tao Hao (called "Hao"), beside
    Lin Tao (called "Tao"); id ``dang`` kept."""
    return renamed(DEFAULT_FILE, (("dang", "Tao Hao", ("Hao",)),), "default with two Taos")
