"""Robots of one fleet driving at once on the office map: they yield to each other through
floor reservations (nav.traffic), never meet, and never wait for each other for ever."""

from __future__ import annotations

import asyncio

import numpy as np

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.errors import BlockedError
from assistantx.core.office import load_office
from assistantx.nav.traffic import Traffic, TrafficParams
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


def test_robots_swapping_desks_stop_beside_the_one_standing_there() -> None:
    """Each robot's goal is where the other stands: neither waits for ever; the first to go
    stops beside the other (a person walks a step further), then the other drives to the
    first's old desk. Nobody touches."""

    async def scenario() -> tuple[Traffic, list[str], list[float]]:
        traffic = Traffic(LoopClock())
        west, east = _robot(traffic, "west", "desk_03"), _robot(traffic, "east", "desk_04")
        arrived = await asyncio.gather(west.move_to("desk_04"), east.move_to("desk_03"))
        misses = []
        for robot, place in ((west, "desk_04"), (east, "desk_03")):
            anchor, pose = robot.anchors[place], robot.state().pose
            misses.append(round(float(np.hypot(pose.x - anchor.x, pose.y - anchor.y)), 2))
        return traffic, [a.place for a in arrived], misses

    traffic, places, misses = run_virtual(scenario)
    assert places == ["desk_04", "desk_03"]
    assert traffic.deadlocks == 0 and traffic.separation_m >= ROBOT_DIAMETER_M
    assert sorted(m > 0.5 for m in misses) == [False, True]  # one stopped beside its desk
    assert max(misses) <= 2.0


def test_a_robot_that_stands_in_the_only_way_for_ever_is_reported_not_driven_into() -> None:
    """A robot parked in the meeting room's one-robot-wide door never moves: the other waits
    its patience out and fails with words naming the robot in the way."""

    async def scenario() -> str:
        traffic = Traffic(LoopClock(), TrafficParams(patience_s=120.0))
        parked = _robot(traffic, "parked", "meeting_room")
        door = _door(parked)
        traffic.stand("parked", *door)
        mover = _robot(traffic, "mover", "desk_08")
        try:
            await mover.move_to("meeting_room")
        except BlockedError as exc:
            return str(exc)
        return "arrived"

    assert run_virtual(scenario).startswith("another robot (parked) has stood in the way")


def _door(robot: NavigatorRobot) -> tuple[float, float]:
    """The narrowest point of the path out of the meeting room: its door."""
    path = robot.plan_to("desk_08").resampled(0.05)
    clearance = [
        robot.navigator.costmap.obstacle_distance_m[robot.grid.world_to_cell(x, y)[::-1]]
        for x, y in path
    ]
    x, y = path[int(np.argmin(clearance))]
    return float(x), float(y)
