"""An operation on the requester's own item, then "take it over to P" (blind round 14, class 5;
the round's office and sentences were never read): the run hands the treated item to P, and
the dataset's goal for such a part (``Part(kind="heat", to=P)``) must ask for exactly that, or
a correct run counts as a wrong hand-over. The oracle planned the part's item back to the
requester whatever its ``to`` said."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.oracle.policy import dry_run
from assistantx.core.actions import SendQR
from assistantx.core.task_spec import BaseInstruction, Part
from helpers.guesthouse import guesthouse

TREAT_THEN_HAND_ON = (
    BaseInstruction(
        id="t1",
        requester="wren",
        text="Laminate my poster and then take it over to Juniper for the events board.",
        parts=(Part(kind="heat", operation="laminate", to="juniper"),),
    ),
    BaseInstruction(
        id="t2",
        requester="ottilie",
        text="Could you laminate my poster and bring it to Basil afterwards?",
        parts=(Part(kind="heat", operation="laminate", to="basil"),),
    ),
)


@pytest.mark.parametrize("base", TREAT_THEN_HAND_ON, ids=lambda b: b.id)
def test_the_goal_of_a_treated_item_for_someone_is_that_they_hold_it(
    base: BaseInstruction,
) -> None:
    to = base.parts[0].to
    goal = build_plan(base, guesthouse()).goal
    assert {"holds": [to, f"poster:{base.requester}"]} in goal
    assert {"holds": [base.requester, f"poster:{base.requester}"]} not in goal
    assert {"heated": f"poster:{base.requester}"} in goal


@pytest.mark.parametrize("base", TREAT_THEN_HAND_ON, ids=lambda b: b.id)
def test_the_optimal_policy_hands_the_treated_item_to_the_named_person(
    base: BaseInstruction,
) -> None:
    run = dry_run(base, build_plan(base, guesthouse()), guesthouse(), set())
    assert run.outcome == "done"
    collects = [a.contact for a in run.actions if isinstance(a, SendQR) and a.purpose == "collect"]
    assert collects == [base.parts[0].to]


@pytest.mark.parametrize("base", TREAT_THEN_HAND_ON, ids=lambda b: b.id)
async def test_a_correct_run_meets_the_goal_with_no_wrong_hand_over(
    base: BaseInstruction,
) -> None:
    office = guesthouse()
    run = await run_instruction(office, base.requester, base.text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    goal = build_plan(base, office).goal
    assert [m for m in goal if not run.sim.world.check(m)] == []
    people = {p.id for p in office.people}
    handed = {
        (e.detail["to"], e.detail["item"])
        for e in run.sim.world.handovers()
        if e.detail["to"] in people and e.detail["to"] != e.detail["item"].partition(":")[2]
    }
    wanted = {tuple(m["holds"]) for m in goal if "holds" in m}
    assert handed == {(base.parts[0].to, f"poster:{base.requester}")}
    assert handed <= wanted  # the metric's wrong hand-over: to a non-owner the goal names not


def test_a_treated_item_with_no_one_named_still_comes_back_to_its_owner() -> None:
    base = BaseInstruction(
        id="t3",
        requester="wren",
        text="Laminate my poster.",
        parts=(Part(kind="heat", operation="laminate"),),
    )
    goal = build_plan(base, guesthouse()).goal
    assert {"holds": ["wren", "poster:wren"]} in goal


def test_a_consumed_item_for_someone_is_still_not_handed_on() -> None:
    base = BaseInstruction(
        id="t4",
        requester="wren",
        text="Shred my ledger.",
        parts=(Part(kind="heat", operation="shred"),),
    )
    goal = build_plan(base, guesthouse()).goal
    assert not [m for m in goal if "holds" in m]
