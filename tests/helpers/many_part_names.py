"""The default office and Harbour with colleagues whose names have several parts, some of
them particles or middle names that are also short English words (Vietnamese "Nguyễn Thị Mai",
"Trần Văn An", Spanish "María de la Cruz", Dutch "Jan van Dijk", Welsh "Rhys ap Dafydd",
Arabic "Omar bin Said"), and one whose given name is such a word without its "s" ("Thi
Lan"), for the reader's tests that no ordinary word stands for a person."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

# id, full name, aliases, desk
PEOPLE: tuple[tuple[str, str, list[str], str], ...] = (
    ("mai", "Nguyễn Thị Mai", ["Mai", "Nguyen Thi Mai"], "desk_01"),
    ("an", "Trần Văn An", ["Tran Van An"], "desk_02"),
    ("maria", "María de la Cruz", ["María", "Maria"], "desk_03"),
    ("jan", "Jan van Dijk", ["Jan"], "desk_04"),
    ("rhys", "Rhys ap Dafydd", ["Rhys"], "desk_05"),
    ("omar", "Omar bin Said", ["Omar"], "desk_06"),
    ("thi", "Thi Lan", [], "desk_07"),
)
ADDED = frozenset(p[0] for p in PEOPLE)


def raw_with_many_part_names(base: Path, kept: str) -> dict[str, Any]:
    """``base``'s office file with the people above, each keeping a paper document, a file
    and a ``kept`` thing."""
    raw: dict[str, Any] = raw_yaml(base)
    for pid, name, aliases, desk in PEOPLE:
        raw["people"].append(
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": desk,
                "handle": f"@{pid}",
                "owns": [
                    {"type": "document", "known": True},
                    {"type": "file", "known": True},
                    {"type": kept, "known": True},
                ],
            }
        )
    return raw


@functools.cache
def default_with_many_part_names() -> Office:
    return parse_office(raw_with_many_part_names(DEFAULT_FILE, "stapler"), "default, many parts")


@functools.cache
def harbour_with_many_part_names() -> Office:
    return parse_office(raw_with_many_part_names(HARBOUR_FILE, "ruler"), "harbour, many parts")
