"""A reasoner that gives up ("failed") with the lender's stapler in the locker: the requester's
last message says the stapler goes back to its owner, and the owner gets it back and is told
why, both in words."""

from __future__ import annotations

import pytest

from assistantx.core.actions import Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.office import Office, load_office
from assistantx.sim.office import SimOffice
from helpers.eventually import eventually
from helpers.office import sim_assistant, started
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


FETCH_THEN_GIVE_UP: list[Step] = [
    [Inquire(contact="zhang", question="Could you lend me your stapler?"), Wait(timeout_s=60)],
    [
        Inform(contact="zhang", content="The robot is coming for your stapler."),
        Move(place="zhang"),
        SendQR(contact="zhang", item="stapler:zhang"),
    ],
    [WaitInPlace(person="zhang")],
    [Stop(outcome="failed", summary="I could not finish bringing you the stapler.")],
]


async def test_a_failed_stop_with_an_item_aboard_tells_both_and_gives_it_back(
    office: Office,
) -> None:
    sim = SimOffice(office)
    assistant = sim_assistant(
        sim, lambda: ScriptedReasoner(list(FETCH_THEN_GIVE_UP)), reasoner_name="scripted"
    )
    async with started(sim, assistant):
        stm = await assistant.submit("lee", "bring me Zhang's stapler")
        await assistant.wait(stm.instruction_id)
        assert stm.trace.outcome == "failed"
        await eventually(
            lambda: sim.world.holder["stapler:zhang"] == "zhang",
            what="Zhang to have his stapler back",
            timeout_s=30,
        )
    lee = [m.text for m in sim.messenger.sent if m.chat.id == "lee"]
    assert lee[-1] == (
        "[failed] I could not finish bringing you the stapler. The robot is bringing "
        "Zhang Wei's stapler back to Zhang Wei."
    )
    zhang = [m.text for m in sim.messenger.sent if m.chat.id == "zhang"]
    told = [t for t in zhang if "is in the robot's locker" in t]
    assert told == [
        "Your stapler is in the robot's locker, and Lee Ming's request it was for could not "
        "be completed. The robot is at your desk to give it back: scan the code I am sending "
        "you to take it out."
    ]
    assert not any("ins-" in t or "stapler:" in t for t in lee + zhang)
