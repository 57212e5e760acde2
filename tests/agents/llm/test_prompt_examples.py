"""The prompts' examples never use the names of the office the assistant serves.

A small model copies its prompt's example (a stapler from a colleague of this very office)
into its answer, and a name it copied looks like one the requester said. So every example
comes from an office nobody runs, or uses placeholders; this test fails on any name, id or
alias of a person, place, facility or group chat of an office of the dataset (the default and
``dataset/offices/*``) in a prompt file or in the built-in prompts.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from assistantx.agents import baselines, hybrid
from assistantx.agents.llm.prompts import DEFAULT_PROMPTS
from assistantx.core import language
from assistantx.core.english import words as english_words
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.core.task_schema import SHAPE_KIND

OFFICES = [None, *sorted(DEFAULT_OFFICE.parent.glob("offices/*/office.yaml"))]


def _office_names() -> set[str]:
    names: set[str] = set()
    for path in OFFICES:
        names |= _names(load_office(path))
    # the task schema's own kinds are words of every office; an id that is an English word
    # ("will", "may") is only a name when written as one ("Will"), which the names check
    english = english_words("common")
    kinds = set(SHAPE_KIND.values())
    return {
        n
        for n in names
        if n
        and n.lower() not in kinds
        and n not in english
        and not (n.islower() and language.is_english_word(n))
    }


def _names(office: Office) -> set[str]:
    names: set[str] = set()
    for person in office.people:
        names |= {person.id, person.name, *person.aliases, *person.name.split()}
    for location in office.locations:
        names.add(location.id)
    for facility in office.facilities:
        names |= {facility.id, facility.name, *facility.synonyms}
    for group in office.groups:
        names |= {group.id, group.name}
    return names


NAMES = _office_names()
PATTERN = re.compile(r"\b(" + "|".join(re.escape(n) for n in sorted(NAMES, key=len)[::-1]) + r")\b")
PROMPTS = sorted(Path(DEFAULT_PROMPTS).rglob("*.md"))


def _hits(text: str) -> list[str]:
    return sorted({m.group(0) for m in PATTERN.finditer(text)})


@pytest.mark.parametrize("path", PROMPTS, ids=lambda p: p.name)
def test_no_prompt_file_names_this_office(path: Path) -> None:
    assert _hits(path.read_text(encoding="utf-8")) == []


def test_every_office_of_the_dataset_is_checked() -> None:
    assert len(OFFICES) >= 2 and "Mark" in NAMES  # a person of the second office


def test_the_built_in_prompts_name_nobody_of_this_office() -> None:
    assert _hits(hybrid.SYSTEM_PROMPT) == []
    assert _hits(baselines.ACTION_SPACE) == []
