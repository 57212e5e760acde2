"""A past participle that is also the name of one of the office's things, after a person's
"'s", is the thing owned: "can I get Wang's forecast?" in an office whose files are called
forecasts asks Wang for his file. Read as "Wang has forecast", the request lost its owner and
the reader sent the requester's own file to Wang (``screen.contracted_is``). A participle
with an object after it is still the verb, and states and whereabouts are read as before."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _forecasting() -> InstructionParser:
    """The default office, whose files are also called forecasts and spreads."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    for t in raw["item_types"]:
        if t["id"] == "file":
            t["synonyms"] = [*t.get("synonyms", []), "forecast", "sales forecast", "spread"]
    return InstructionParser(parse_office(raw))


def _read(text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _forecasting().parse(text, "lin")
    assert frame.question is None, frame.question
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can i get wang's forecast?",
        "can I get Wang's forecast? the one she did this morning",
        "could you send me Wang's spread",
        "grab me Wang's sales forecast pls",
    ],
)
def test_the_participle_named_thing_is_owned(text: str) -> None:
    assert _read(text) == [("send_file", "file", "wang", "lin")]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # a state word keeps its reading: the stapler is broken, the request is the coffee
        ("Wang's stapler is broken, bring me a coffee", [("produce", "coffee", None, "lin")]),
        # whereabouts: Zhang is away, the stapler asked for is anyone's
        ("Zhang's gone home, can you bring me a stapler", [("transfer", "stapler", None, "lin")]),
    ],
)
def test_states_and_whereabouts_as_before(
    text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text) == tasks


def test_a_participle_with_its_object_is_the_verb() -> None:
    """ "Wang's forecast another busy week": Wang has forecast it; no file is asked for."""
    frame = _forecasting().parse("Wang's forecast another busy week", "lin")
    assert not frame.tasks, frame
