"""A full name whose family name has a hyphen ("Ana Souza-Lima") names that one colleague,
typed with the hyphen, with a space for it, or given as the answer to "Who do you mean by
'Ana'"; the given name alone, shared by two, is still asked. A guard for blind round 135's
class (the reader held here on main already: no mechanism was added for it)."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE

# two colleagues who share a given name, one family name hyphenated; harbour writes family
# names last, the default office first (so "Marta" is declared as the alias)
_RENAMED = {
    "harbour": {"may": ("Ana Souza-Lima", ["Ana"]), "mark": ("Ana Berg", ["Ana"])},
    "default": {"wang": ("Marta Ferreira-Lopes", ["Marta"]), "zhang": ("Marta Silva", ["Marta"])},
}
_REQUESTER = {"harbour": "will", "default": "lin"}


@functools.cache
def _parser(base: str) -> InstructionParser:
    source = HARBOUR_FILE if base == "harbour" else DEFAULT_FILE
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(source.read_text(encoding="utf-8")))
    for p in raw["people"]:
        if p["id"] in _RENAMED[base]:
            p["name"], p["aliases"] = _RENAMED[base][p["id"]][0], list(_RENAMED[base][p["id"]][1])
    return InstructionParser(parse_office(raw, f"{base} with a hyphenated family name"))


def _recipients(base: str, text: str, answers: tuple[str, ...] = ()) -> list[str | None]:
    frame = _parser(base).parse_with_answers(text, _REQUESTER[base], list(answers))
    assert frame.question is None, frame.question
    return [t.recipient for t in frame.tasks]


@pytest.mark.parametrize(
    ("base", "text", "answers", "who"),
    [
        ("harbour", "take my calculator to Ana Souza-Lima", (), "may"),
        ("harbour", "give Ana Souza Lima my calculator", (), "may"),
        ("harbour", "take my calculator to ana souza-lima please", (), "may"),
        ("harbour", "take my calculator to Ana", ("Ana Souza-Lima",), "may"),
        ("harbour", "take my calculator to Ana", ("Ana Berg",), "mark"),
        ("default", "copy my document and take the copy to Marta Ferreira-Lopes", (), "wang"),
        (
            "default",
            "copy my document and take the copy to Marta",
            ("Marta Ferreira-Lopes",),
            "wang",
        ),
        ("default", "copy my document and take the copy to Marta Silva", (), "zhang"),
    ],
)
def test_the_hyphenated_full_name_is_that_colleague(
    base: str, text: str, answers: tuple[str, ...], who: str
) -> None:
    assert _recipients(base, text, answers) == [who]


@pytest.mark.parametrize(
    ("base", "text"),
    [("harbour", "take my calculator to Ana"), ("default", "take my document to Marta")],
)
def test_the_shared_given_name_alone_is_asked(base: str, text: str) -> None:
    # must not change: two colleagues answer to the given name; nothing moves before the answer
    frame = _parser(base).parse(text, _REQUESTER[base])
    assert not frame.tasks
    assert frame.question is not None and "Who do you mean by" in frame.question
