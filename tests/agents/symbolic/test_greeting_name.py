"""People are greeted by the name people use (``core.name_parts.greeting_name``): the office's
first one-word alias that is a word of their full name ("Hi Mai" for Nguyễn Thị Mai, whose
alias is Mai), else the first word of the full name; never the family name said first."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.name_parts import greeting_name
from assistantx.core.office import Office, load_office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

_NAMES = {
    "may": ("Nguyễn Thị Mai", ["Mai"]),
    "will": ("Trần Văn Hùng", ["Boss", "Hùng", "Mr Trần"]),
    "rose": ("Kim Seo Yeon", ["Seo Yeon"]),
    "pat": ("Ms Pat Nowak", []),
}


@functools.cache
def _office() -> Office:
    """Harbour whose people include family-name-first names."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    for p in raw["people"]:
        if p["id"] in _NAMES:
            p["name"], p["aliases"] = _NAMES[p["id"]][0], list(_NAMES[p["id"]][1])
    return parse_office(raw, "harbour with family names first")


@pytest.mark.parametrize(
    ("person", "called"),
    [
        ("may", "Mai"),  # the alias that is her given name
        ("will", "Hùng"),  # "Boss" is no word of his name; the next alias is
        ("rose", "Kim"),  # no one-word alias: the first word of the name
        ("pat", "Pat"),  # a title written into the name is no name
        ("mark", "Mark"),
    ],
)
def test_greeting_name(person: str, called: str) -> None:
    assert greeting_name(_office().person(person)) == called


def test_default_office_greets_by_the_declared_given_name() -> None:
    office = load_office(DEFAULT_FILE)
    assert greeting_name(office.person("zhang")) == "Wei"  # Zhang Wei, called Wei
    assert greeting_name(office.person("sun")) == "Sun"  # Sun Li's alias "Li Sun" is two words


@pytest.mark.parametrize(
    ("requester", "text", "asked", "hello"),
    [
        ("mark", "bring my ruler to Mai", "may", "Hi Mai,"),
        ("mark", "take my ruler to Hùng", "will", "Hi Hùng,"),
    ],
)
async def test_messages_greet_by_that_name(
    requester: str, text: str, asked: str, hello: str
) -> None:
    run = await run_instruction(_office(), requester, text)
    questions = [
        r.action.question
        for r in run.stm.trace.actions()
        if r.action.type == "inquire" and r.action.contact == asked
    ]
    assert questions and all(q.startswith(hello) for q in questions), questions
