"""The prompts' examples never use the names of the office the assistant serves.

A small model copies its prompt's example (a stapler from a colleague of this very office)
into its answer, and a name it copied looks like one the requester said. So every example
comes from another office or uses placeholders; this test fails on any name, id or alias of a
person, place, facility or group chat of the default office in a prompt file or in the
hybrid's understanding prompt.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from assistantx.agents import baselines, hybrid
from assistantx.agents.llm.prompts import DEFAULT_PROMPTS
from assistantx.core.office import load_office
from assistantx.core.task_schema import SHAPE_KIND


def _office_names() -> set[str]:
    office = load_office()
    names: set[str] = set()
    for person in office.people:
        names |= {person.id, person.name, *person.aliases, *person.name.split()}
    for location in office.locations:
        names.add(location.id)
    for facility in office.facilities:
        names |= {facility.id, facility.name, *facility.synonyms}
    for group in office.groups:
        names |= {group.id, group.name}
    # the task schema's own kinds are words of every office
    return {n for n in names if n and n.lower() not in set(SHAPE_KIND.values())}


NAMES = _office_names()
PATTERN = re.compile(r"\b(" + "|".join(re.escape(n) for n in sorted(NAMES, key=len)[::-1]) + r")\b")
PROMPTS = sorted(Path(DEFAULT_PROMPTS).rglob("*.md"))


def _hits(text: str) -> list[str]:
    return sorted({m.group(0) for m in PATTERN.finditer(text)})


@pytest.mark.parametrize("path", PROMPTS, ids=lambda p: p.name)
def test_no_prompt_file_names_this_office(path: Path) -> None:
    assert _hits(path.read_text(encoding="utf-8")) == []


def test_the_built_in_prompts_name_nobody_of_this_office() -> None:
    assert _hits(hybrid.SYSTEM_PROMPT) == []
    assert _hits(baselines.ACTION_SPACE) == []
