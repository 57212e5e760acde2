"""Robots of one fleet driving at once on the office map: they yield to each other through
floor reservations (nav.traffic), never meet, and never wait for each other for ever."""

from __future__ import annotations

import asyncio

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.office import load_office
from assistantx.nav.traffic import Traffic
from assistantx.sim.virtual_time import LoopClock, run_virtual

ROBOT_DIAMETER_M = 0.5


def _robot(traffic: Traffic, name: str, start: str) -> NavigatorRobot:
    return NavigatorRobot.from_files(
        load_office(), LoopClock(), localize=False, start=start, traffic=traffic, name=name
    )


def test_two_robots_crossing_the_meeting_room_door_both_arrive_and_never_touch() -> None:
    """The meeting room's door is one robot wide; one robot drives out through it while the
    other drives in. Both arrive; one of them waited for the other; they never came closer
    than a robot's width."""

    async def scenario() -> tuple[Traffic, list[str], float]:
        traffic = Traffic(LoopClock())
        inside = _robot(traffic, "inside", "meeting_room")
        outside = _robot(traffic, "outside", "desk_08")
        arrived = await asyncio.gather(inside.move_to("desk_16"), outside.move_to("meeting_room"))
        return traffic, [a.place for a in arrived], asyncio.get_running_loop().time()

    traffic, places, ended_s = run_virtual(scenario)
    assert places == ["desk_16", "meeting_room"]
    assert traffic.deadlocks == 0
    assert traffic.separation_m >= ROBOT_DIAMETER_M
    waits = sorted(w for _, w in traffic.waits)
    assert waits[0] == 0.0 and waits[1] > 0.0  # one went first, the other yielded
    assert ended_s < 120.0  # in simulated time: the yielding robot went on as soon as it could


def test_robots_head_on_along_the_desks_aisle_take_turns_or_go_round() -> None:
    """Four robots at once along the aisle whose desks' stops lie on one line, two each way,
    passing where the others start and end: every robot arrives and no two ever come within
    a robot's width."""

    async def scenario() -> tuple[Traffic, list[str]]:
        traffic = Traffic(LoopClock())
        trips = [("desk_01", "desk_05"), ("desk_06", "desk_02"), ("desk_03", "desk_07")]
        trips.append(("desk_08", "desk_04"))
        robots = [_robot(traffic, f"r{n}", a) for n, (a, _) in enumerate(trips)]
        arrived = await asyncio.gather(
            *(r.move_to(b) for r, (_, b) in zip(robots, trips, strict=True))
        )
        return traffic, [a.place for a in arrived]

    traffic, places = run_virtual(scenario)
    assert places == ["desk_05", "desk_02", "desk_07", "desk_04"]
    assert traffic.deadlocks == 0
    assert traffic.separation_m >= ROBOT_DIAMETER_M


def test_a_robot_standing_in_the_way_is_waited_for_then_reported_not_driven_into() -> None:
    """A robot parked on the other's goal never moves: the other waits its patience out and
    fails with words naming the robot in the way, instead of driving into it."""

    async def scenario() -> str:
        traffic = Traffic(LoopClock())
        _robot(traffic, "parked", "desk_03")
        mover = _robot(traffic, "mover", "desk_01")
        try:
            await mover.move_to("desk_03")
        except Exception as exc:
            return f"{type(exc).__name__}: {exc}"
        return "arrived"

    outcome = run_virtual(scenario)
    assert outcome.startswith("BlockedError: another robot (parked) has stood in the way")
