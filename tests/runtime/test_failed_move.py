"""A failed move is a fact: the same failure twice ends the instruction with words, not a
retry loop, and the requester learns where the robot and the locker's contents are."""

from __future__ import annotations

import pytest

from assistantx.core.actions import Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.errors import BlockedError
from assistantx.core.office import Office, load_office
from assistantx.core.ports.robot import MoveResult
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from assistantx.sim.robot import SimRobot
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


class RoadBlockedTo(SimRobot):
    """The physical world: every way to ``blocked`` is blocked (the robot does not move)."""

    def __init__(self, office: Office, sim_clock: object, blocked: str) -> None:
        super().__init__(office, sim_clock, office.distance, office.robot.speed_mps)  # type: ignore[arg-type]
        self.blocked = blocked
        self.attempts = 0

    async def move_to(self, location_id: str) -> MoveResult:
        if location_id == self.blocked:
            self.attempts += 1
            raise BlockedError("the way to (2.00, 3.00) is blocked")
        return await super().move_to(location_id)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _run(office: Office, steps: list[Step]) -> tuple[ShortTermMemory, SimOffice, int]:
    lee_desk = office.person("lee").location
    sim = SimOffice(office)
    robot = RoadBlockedTo(office, sim.clock, lee_desk)
    sim = SimOffice(office, clock=sim.clock, robot=robot)
    assistant = sim_assistant(
        sim,
        lambda: ScriptedReasoner(steps),
        reasoner_name="scripted",
        limits=LoopLimits(max_steps=30),
    )
    stm = await run_one(sim, assistant, "lee", "bring me Zhang's stapler")
    return stm, sim, robot.attempts


FETCH_STAPLER: list[Step] = [
    [Inquire(contact="zhang", question="Could you lend me your stapler?"), Wait(timeout_s=60)],
    [
        Inform(contact="zhang", content="The robot is coming for your stapler."),
        Move(place="zhang"),
        SendQR(contact="zhang", item="stapler:zhang"),
    ],
    [WaitInPlace(person="zhang")],
]


async def test_blocked_drive_with_the_item_in_the_locker_ends_in_words(office: Office) -> None:
    # A reasoner that insists on the same move, as the symbolic one did 28 times.
    steps = list(FETCH_STAPLER) + [[Move(place="lee")] for _ in range(20)]
    stm, sim, attempts = await _run(office, steps)
    assert attempts == 2  # one retry, then the failure is a fact
    assert stm.trace.outcome == "failed"
    told = [t.text for t in stm.dialogue if t.direction == "out" and t.person == "lee"]
    last = told[-1]
    assert office.location(office.person("lee").location).name in last
    assert "Zhang" in last and "stapler" in last and "locked in its locker" in last
    assert "something blocks the way" in last and "(2.00" not in last
    zhang_place = office.location(office.person("zhang").location).name
    assert f"at {zhang_place}" in last  # where the robot is, by name
    assert "stapler:zhang" not in last and "lee" not in last.split()  # no internal ids
    assert stm.embodied.locker_contents == ["stapler:zhang"]
    assert sim.world.check({"holds": ["lee", "stapler:zhang"]}) is False


async def test_blocked_drive_with_an_empty_locker(office: Office) -> None:
    steps: list[Step] = [[Move(place="lee")] for _ in range(10)]
    stm, _, attempts = await _run(office, steps)
    assert attempts == 2
    assert stm.trace.outcome == "failed"
    last = [t.text for t in stm.dialogue if t.direction == "out" and t.person == "lee"][-1]
    assert "its locker is empty" in last


async def test_a_different_failure_is_not_cut_short(office: Office) -> None:
    # Move to Lee fails, then the reasoner does something else that works and stops: the
    # single failure does not end the instruction.
    steps: list[Step] = [
        [Move(place="lee")],
        [Inform(contact="lee", content="The way to your desk is blocked.")],
        [Stop(outcome="failed", summary="The way to your desk is blocked.")],
    ]
    stm, _, attempts = await _run(office, steps)
    assert attempts == 1
    assert stm.trace.summary == "The way to your desk is blocked."
