"""A swap with one colleague ("take my scissors to Zhang and bring me back his stapler"):
the colleague receives the requester's item and lends their own. The optimal policy asks
them both things in one question, in their own chat, so their yes covers the lend; before,
the second question for the same person was dropped, the lend had no yes, and every variant
of the base ended "failed" (blind round 72's writer found it with the parts in this order)."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.task_spec import BaseInstruction, Part
from helpers.dataset_offices import default_office
from helpers.dataset_tasks import verify_every_variant

DELIVER_THEN_LEND = BaseInstruction(
    id="swap1",
    requester="sun",
    text="Take my scissors to Zhang and bring me back his stapler",
    parts=(
        Part(kind="deliver", item="scissors", to="zhang"),
        Part(kind="fetch", item="stapler", owner="zhang"),
    ),
)
LEND_THEN_DELIVER = BaseInstruction(
    id="swap2",
    requester="sun",
    text="Bring me Zhang's stapler and take him my scissors",
    parts=(
        Part(kind="fetch", item="stapler", owner="zhang"),
        Part(kind="deliver", item="scissors", to="zhang"),
    ),
)


@pytest.mark.parametrize(
    "base", [DELIVER_THEN_LEND, LEND_THEN_DELIVER], ids=["deliver-first", "lend-first"]
)
def test_the_colleague_is_asked_once_for_both_and_the_lend_is_named(base: BaseInstruction) -> None:
    plan = build_plan(base, default_office())
    zhang = [r for r in plan.roles if r.person == "zhang"]
    assert len(zhang) == 1
    question = zhang[0].question
    assert "lend Sun Li your stapler" in question
    assert "be at your desk" in question


@pytest.mark.parametrize(
    "base", [DELIVER_THEN_LEND, LEND_THEN_DELIVER], ids=["deliver-first", "lend-first"]
)
def test_every_variant_of_the_swap_is_solved_as_labelled(base: BaseInstruction) -> None:
    tasks = asyncio.run(verify_every_variant(default_office(), base))
    done = [t for t in tasks if t.achievable]
    assert done and all(
        {"holds": ["zhang", "scissors:sun"]} in t.goal
        and {"holds": ["sun", "stapler:zhang"]} in t.goal
        for t in done
    )
