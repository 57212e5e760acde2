"""An office whose operations the code has never heard of (scan, boil, laminate, frank, a
cupboard that keeps things) runs its tasks to done in the simulated office, unchanged."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Office


@pytest.mark.parametrize(
    ("requester", "text", "milestones"),
    [
        ("will", "Make me a cup of tea, please.", [{"holds": ["will", "tea:will"]}]),
        ("grace", "Scan my contract for me.", [{"holds": ["grace", "scan:grace"]}]),
        ("bill", "Please laminate my badge.", [{"heated": "badge:bill"}]),
        ("may", "Can you get me a stamped envelope?", [{"holds": ["may", "stamped_envelope:may"]}]),
        (
            "hope",
            "Fetch May's label maker from the stationery cupboard, please.",
            [{"holds": ["hope", "label_maker:may"]}],
        ),
    ],
)
async def test_new_operations_run_to_done(
    harbour: Office, requester: str, text: str, milestones: list[dict[str, Any]]
) -> None:
    run = await run_instruction(harbour, requester, text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    for m in milestones:
        assert run.sim.world.check(m), m
    # nothing went to anyone but the requester
    assert {
        e.detail["to"] for e in run.sim.world.handovers() if e.detail.get("to") != "locker"
    } <= {requester}


async def test_an_operation_the_office_lacks_is_declined_there(harbour: Office) -> None:
    run = await run_instruction(harbour, "will", "make me a coffee")
    assert run.stm.trace.outcome == "unachievable"
    assert run.actions == ["stop"]
    assert "kettle" in run.sim.messenger.sent[-1].text  # names what it can do instead
