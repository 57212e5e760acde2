"""The task schema is the one contract between understanding and planning (issue 16).

The dataset writes each base instruction's meaning as ``parts`` (``task_schema.Part``); read
as the schema's ``Task``s they must be exactly what the embedded parser reads from the
instruction's text, in both offices. So the spec, the parser and the planner share one
vocabulary, and a disagreement shows up here case by case.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core import task_kinds
from assistantx.core.goals import PREDICATES
from assistantx.core.office import Office, load_office
from assistantx.core.task_schema import Part, Task, kind_shape
from assistantx.core.task_spec import BaseInstruction, load_base_instructions

ROOT = Path(__file__).resolve().parents[2] / "dataset"
OFFICES = {"default": ROOT, "harbour": ROOT / "offices" / "harbour"}


def _bases() -> list[tuple[str, BaseInstruction]]:
    found = []
    for name, folder in OFFICES.items():
        office = load_office(folder / "office.yaml")
        found += [
            (name, b) for b in load_base_instructions(folder / "base_instructions.yaml", office)
        ]
    return found


_OFFICES: dict[str, Office] = {n: load_office(f / "office.yaml") for n, f in OFFICES.items()}


def _key(task: Task) -> tuple[str, str | None, str | None, str, str | None]:
    return (task.kind, task.item, task.owner, task.recipient, task.actor)


@pytest.mark.parametrize(("office", "base"), _bases(), ids=lambda v: getattr(v, "id", v))
def test_the_parser_reads_the_text_as_its_parts(office: str, base: BaseInstruction) -> None:
    o = _OFFICES[office]
    frame = InstructionParser(o).parse(base.text, base.requester)
    assert frame.understood, (frame.question, frame.decline)
    assert {_key(t) for t in frame.tasks} == {_key(t) for t in base.tasks(o)}


def test_a_part_reads_as_a_task_of_the_schema() -> None:
    office = _OFFICES["default"]
    copy = Part(kind="copy").task("wang", office)
    assert (copy.kind, copy.owner, copy.recipient) == ("copy", "wang", "wang")
    assert copy.input_item is not None and copy.operation is not None
    assert kind_shape(copy.kind) == "transform"
    fetch = Part(kind="fetch", item="stapler", owner="zhang").task("wang", office)
    assert (fetch.kind, fetch.item, fetch.owner, fetch.recipient) == (
        "transfer",
        "stapler",
        "zhang",
        "wang",
    )
    assert Part(kind="get_file", owner="lee").task("wang", office).kind == "send_file"


def test_every_milestone_but_informed_names_a_task_kind() -> None:
    assert {k.milestone for k in task_kinds.kinds()} == set(PREDICATES) - {"informed"}
