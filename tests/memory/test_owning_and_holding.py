"""Owning and holding are different facts. After Lee holds Wang's stapler (a hand-over the
assistant made), Wang still owns it: "I don't have a stapler" from Wang erases nothing, and
a second request for a stapler does not send the robot to Wang."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import build_factory
from assistantx.core.office import Office, load_office
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.render import render_long_term
from assistantx.memory.updates import ItemLocationUpdate, OwnershipUpdate
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant, started


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def test_saying_you_do_not_have_a_lent_item_keeps_its_ownership(office: Office) -> None:
    ltm = LongTermMemory(office)
    assert ltm.ownership("wang", "stapler") is True
    ltm.apply(ItemLocationUpdate(item="stapler:wang", holder="lee", evidence="lee collected"), 1)
    applied = ltm.apply(
        OwnershipUpdate(person="wang", item_type="stapler", owns=False, evidence="no"), 2
    )
    assert not applied.changed
    assert ltm.ownership("wang", "stapler") is True
    assert "wang" in ltm.owners("stapler")
    assert ltm.item_holder("stapler:wang") == "lee"
    assert "wang" not in ltm.lenders("stapler")
    assert "stapler (held by lee)" in render_long_term(ltm)


def test_an_owner_whose_item_is_at_home_can_still_be_told_they_lack_one(
    office: Office,
) -> None:
    ltm = LongTermMemory(office)
    ltm.apply(OwnershipUpdate(person="wang", item_type="stapler", owns=False, evidence="no"), 1)
    assert ltm.ownership("wang", "stapler") is False


async def test_a_second_request_does_not_go_to_the_owner_whose_item_is_lent(
    office: Office,
) -> None:
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, None))
    async with started(sim, assistant):
        first = await assistant.wait(
            (await assistant.submit("lee", "Bring me a stapler")).instruction_id
        )
        assert first.trace.outcome == "done"
        lender = next(o for o in ("wang", "zhang") if sim.world.holder.get(f"stapler:{o}") == "lee")
        assert assistant.ltm.item_holder(f"stapler:{lender}") == "lee"
        second = await assistant.wait(
            (await assistant.submit("hu", "Bring me a stapler")).instruction_id
        )
    asked = {
        r.action.contact  # type: ignore[union-attr]
        for r in second.trace.actions()
        if r.action.type in ("inquire", "send_qr")
    }
    assert lender not in asked
    assert second.trace.outcome == "done"
    assert assistant.ltm.ownership(lender, "stapler") is True
