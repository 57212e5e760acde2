"""A purpose phrase names the tool by its purpose, object and all: "something to check
continuity with" is the item whose purposes include "check continuity", the object noun
("continuity") part of the purpose and never glued to the item's name. Before, "check" alone
was matched after "check continuity" had chosen the multimeter, and the rest read "a
multimeter continuity with?" ("there is no multimeter continuity in this office"). Purposes
of one word ("something to cut paper with", "something to write with") read as before."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE, default_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


def _with_tool(path: Any, owner: str, entry: dict[str, Any]) -> Office:
    """The office at ``path`` with one more item type, owned by ``owner``."""
    raw = raw_yaml(path)
    raw["item_types"].append(entry)
    person = next(p for p in raw["people"] if p["id"] == owner)
    person.setdefault("owns", []).append({"type": entry["id"]})
    return parse_office(raw)


@functools.cache
def _harbour_with_meter() -> Office:
    # a multimeter whose purposes are two-word phrases, verb and object
    return _with_tool(
        HARBOUR_FILE,
        "ken",
        {
            "id": "multimeter",
            "name": "multimeter",
            "purposes": ["check continuity", "measure voltage"],
        },
    )


@functools.cache
def _default_with_gauge() -> Office:
    return _with_tool(
        DEFAULT_FILE,
        "lin",
        {"id": "gauge", "name": "tyre gauge", "purposes": ["check pressure", "test tyres"]},
    )


_harbour = frame_reader(_harbour_with_meter, "will")
_default = frame_reader(_default_with_gauge, "mao")
_plain = frame_reader(default_office, "mao")


def _read(office: str, text: str) -> TaskFrame:
    return {"harbour": _harbour, "default": _default, "plain": _plain}[office](text)


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        (
            "harbour",
            "can you find me something to check continuity with? loom is playing up",
            "multimeter",
        ),
        ("harbour", "i need something to measure voltage with", "multimeter"),
        ("harbour", "something to check continuity on the loom with pls", "multimeter"),
        ("harbour", "could you bring me something to check continuity", "multimeter"),
        (
            "default",
            "can you get me something to check pressure with? van tyre looks flat",
            "gauge",
        ),
        ("default", "anything i can test tyres with?", "gauge"),
        # the neighbours: one-word purposes, as before
        ("plain", "can you find me something to cut paper with?", "scissors"),
        ("plain", "can you find me something to write with?", "pen"),
        ("harbour", "can you find me something to draw lines with?", "ruler"),
    ],
)
def test_the_purpose_names_the_tool(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert frame.decline is None and frame.question is None, (frame.decline, frame.question)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)]


def test_a_purpose_nothing_serves_is_still_said_so() -> None:
    # no item of the office checks the oil: nothing made up from the purpose's words
    frame = _harbour("can you find me something to check the oil with?")
    assert frame.tasks == []
