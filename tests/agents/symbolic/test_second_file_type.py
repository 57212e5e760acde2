"""An office with two kinds of electronic file (a general document file, and audio that
only the CD burner takes): the file sent to the burner's keeper is the audio, not the
person's general file. Found by a blind writer (a local radio station) whose task set did
not verify: the optimal policy forwarded the general file, which the locker rules refused."""

from __future__ import annotations

import asyncio
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.office import Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from helpers import office_builder as ob
from helpers.archive import raw_archive
from helpers.dataset_tasks import verify_every_variant


def _studio() -> Office:
    raw: dict[str, Any] = raw_archive()
    raw["item_types"] += [
        ob.item("audio", "audio file", "electronic", synonyms=["recording", "clip"]),
        ob.item("cd", "CD", "product", synonyms=["disc"]),
    ]
    raw["operations"].append(
        ob.operation("burn", "burn", name="burn to CD", input="audio", product="cd")
    )
    raw["facilities"].append(
        ob.facility(
            "cd_burner",
            "CD burner",
            at="stack_room",
            guards=["mira", "oskar"],
            operations=["burn"],
            products=["cd"],
        )
    )
    for person in raw["people"]:
        person["owns"].append({"type": "audio"})
    return parse_office(raw, raw["name"])


BURN = BaseInstruction(
    id="b1",
    requester="ines",
    text="Can you burn my recording onto a CD for me?",
    parts=(Part(kind="print", operation="burn"),),
)
PRINT = BaseInstruction(
    id="p1",
    requester="ines",
    text="Can you print my document?",
    parts=(Part(kind="print", operation="print"),),
)


def test_the_burn_is_of_the_audio_file() -> None:
    office = _studio()
    check_base(BURN, office)
    plan = build_plan(BURN, office)
    assert [f.file for f in plan.forwards] == ["audio:ines"]
    assert {"printed": "audio:ines"} in plan.goal


@pytest.mark.parametrize("base", [BURN, PRINT], ids=lambda b: b.id)
def test_every_variant_is_solved_with_the_file_the_work_takes(base: BaseInstruction) -> None:
    """Near-miss beside it: the printer's work still sends the general document file."""
    tasks = asyncio.run(verify_every_variant(_studio(), base))
    assert any(t.achievable for t in tasks)


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("can you burn my recording onto a CD for me?", "audio:ines"),
        ("could you print my document?", "doc_file:ines"),
    ],
)
async def test_the_assistant_sends_the_file_the_work_takes(text: str, sent: str) -> None:
    """The embedded assistant, end to end in the simulated office, does the same."""
    run = await run_instruction(_studio(), "ines", text)
    files = {
        r.action.file or run.sim.office.file_of(r.action.source)
        for r in run.stm.trace.actions()
        if r.action.type == "forward_file" and not r.refused
    }
    assert files == {sent}
    assert run.stm.trace.outcome == "done"
