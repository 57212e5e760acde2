"""Walking saved against path lengths measured independently on the office map."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.actions import Move, Stop
from assistantx.core.clock import SimClock
from assistantx.core.errors import UnreachableError
from assistantx.core.office import Office
from assistantx.core.trace import ActionResult, Trace
from assistantx.feedback.walking import estimate_walking, over_map
from assistantx.sim.robot import ObservedRobot, SimRobot

from .scripted import harness


@pytest.fixture(scope="module")
def robot(office: Office) -> NavigatorRobot:
    return NavigatorRobot.from_files(office, SimClock(), localize=False)


def _planned_length(robot: NavigatorRobot, a: str, b: str) -> float:
    """Plan the leg afresh and add up the lengths of the path's segments."""
    start, goal = robot.anchors[a], robot.anchors[b]
    path = robot.navigator.planner.plan((start.x, start.y), (goal.x, goal.y))
    return float(np.hypot(*np.diff(path.points, axis=0).T).sum())


def _route_length(robot: NavigatorRobot, route: list[str]) -> float:
    return sum(_planned_length(robot, a, b) for a, b in itertools.pairwise(route))


async def test_walking_saved_matches_hand_computed_paths(
    office: Office, robot: NavigatorRobot, tmp_path: Path
) -> None:
    async with harness(office, tmp_path / "j.sqlite3", distance=over_map(robot)) as h:
        printout = await h.run(
            "lee",
            "fetch my printout",
            [[Move(place="printer")], [Move(place="lee")], [Stop(outcome="done", summary="ok")]],
        )
        two_things = await h.run(
            "hu",
            "bring me Gao's stapler and Wu's paper",
            [
                [Move(place="gao")],
                [Move(place="wu")],
                [Move(place="hu")],
                [Stop(outcome="done", summary="both here")],
            ],
        )
        first = h.store.instruction(printout.instruction_id)
        second = h.store.instruction(two_things.instruction_id)
    assert first is not None and second is not None

    lee_walk = _route_length(robot, ["desk_03", "print_room", "desk_03"])
    hu_walk = _route_length(robot, ["desk_10", "desk_12", "desk_15", "desk_10"])
    assert first.walking.route == ["desk_03", "print_room", "desk_03"]
    assert second.walking.route == ["desk_10", "desk_12", "desk_15", "desk_10"]
    assert first.walking.method == second.walking.method == "map"
    assert first.walking.walk_m == pytest.approx(lee_walk, abs=1e-3)
    assert second.walking.walk_m == pytest.approx(hu_walk, abs=1e-3)
    assert first.walking.saved_m == first.walking.walk_m
    # The map's paths go round walls: longer than the straight line to the print room.
    straight = sum(office.distance(a, b) for a, b in itertools.pairwise(first.walking.route))
    assert lee_walk > straight + 0.5

    # The robot drove from its home to the printer and Lee, then on to Gao, Wu and Hu.
    robot_first = _route_length(robot, ["meeting_room", "print_room", "desk_03"])
    robot_second = _route_length(robot, ["desk_03", "desk_12", "desk_15", "desk_10"])
    assert first.walking.robot_m == pytest.approx(robot_first, abs=1e-3)
    assert second.walking.robot_m == pytest.approx(robot_second, abs=1e-3)


def _trace(requester: str, outcome: str | None, places: list[str]) -> Trace:
    trace = Trace(instruction_id="i", requester=requester, text="t", reasoner="x", started_at=0)
    trace.outcome = outcome  # type: ignore[assignment]
    from assistantx.core.trace import TraceStep

    step = TraceStep(index=0, started_at=0)
    for place in places:
        step.results.append(
            ActionResult(
                action=Move(place=place),
                ok=True,
                observation="arrived",
                started_at=0,
                ended_at=1,
                data={"distance_m": 2.0},
            )
        )
    trace.steps.append(step)
    return trace


def test_only_done_instructions_save_walking(office: Office) -> None:
    failed = estimate_walking(office, _trace("lee", "failed", ["desk_04"]))
    assert failed.walk_m == pytest.approx(2 * office.distance("desk_03", "desk_04"), abs=1e-3)
    assert failed.saved_m == 0.0
    assert failed.method == "straight-line"
    assert failed.robot_m == 2.0


def test_no_trip_saves_nothing(office: Office) -> None:
    estimate = estimate_walking(office, _trace("lee", "done", []))
    assert estimate.route == ["desk_03"]
    assert estimate.walk_m == 0.0 == estimate.saved_m


def test_unreachable_leg_falls_back_to_straight_lines(office: Office) -> None:
    def cut_off(a: str, b: str) -> float:
        raise UnreachableError(f"no path from {a} to {b}")

    estimate = estimate_walking(office, _trace("lee", "done", ["desk_04"]), cut_off)
    assert estimate.method == "straight-line"
    assert estimate.saved_m == pytest.approx(2 * office.distance("desk_03", "desk_04"), abs=1e-3)


def test_a_base_without_a_map_is_measured_in_straight_lines(office: Office) -> None:
    kinematic = SimRobot(office, SimClock(), office.distance, speed_mps=1.0)
    estimate = estimate_walking(office, _trace("lee", "done", ["desk_04"]), over_map(kinematic))
    assert estimate.method == "straight-line"
    assert estimate.walk_m == pytest.approx(2 * office.distance("desk_03", "desk_04"), abs=1e-3)


def test_the_simulated_office_measures_over_the_base_it_observes(
    office: Office, robot: NavigatorRobot
) -> None:
    observed = ObservedRobot(robot, office.robot.home)
    estimate = estimate_walking(office, _trace("lee", "done", ["print_room"]), over_map(observed))
    assert estimate.method == "map"
    assert estimate.walk_m == pytest.approx(
        _route_length(robot, ["desk_03", "print_room", "desk_03"]), abs=1e-3
    )
