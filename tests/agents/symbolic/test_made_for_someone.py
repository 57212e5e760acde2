"""A thing made for someone else ("make Mark a tea", "take the scan to Mark") ends in their
hands, and that is what the dataset's goal for it asks (issue 23, outside evaluation): a
correct run of the embedded agent meets every milestone the generator labels the task with."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction, Part

BASES = (
    BaseInstruction(
        id="m1",
        requester="may",
        text="Could you bring Mark a cup of tea?",
        parts=(Part(kind="tea", to="mark"),),
    ),
    BaseInstruction(
        id="m2",
        requester="may",
        text="Could you scan my contract and take the scan to Mark?",
        parts=(Part(kind="copy", to="mark"),),
    ),
)


@pytest.mark.parametrize("base", BASES, ids=lambda b: b.id)
async def test_a_correct_run_meets_the_generated_goal(
    harbour: Office, base: BaseInstruction
) -> None:
    run = await run_instruction(harbour, base.requester, base.text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    goal = build_plan(base, harbour).goal
    assert {"informed": "may"} in goal
    assert [m for m in goal if not run.sim.world.check(m)] == []
