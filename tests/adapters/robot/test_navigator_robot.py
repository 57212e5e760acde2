"""NavigatorRobot on the committed office map, with a SimClock: driving between anchors,
the fast kinematic mode, path distances and each typed failure."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import SimClock
from assistantx.core.errors import BlockedError, LocalizationLostError, MapError, UnreachableError
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.nav.anchors import Anchor
from assistantx.nav.navigation import NavigationParams
from assistantx.nav.occupancy_map import OccupancyMap


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office(DEFAULT_OFFICE)


def _robot(
    office: Office,
    grid: OccupancyMap,
    anchors: dict[str, Anchor],
    clock: SimClock,
    *,
    localize: bool,
    start: str,
    plan_in_process: bool = False,
) -> NavigatorRobot:
    """The robot of these tests. Localizing, it plans here rather than in the service's
    planning worker process (``plan_in_process``, the default of a localizing robot) unless a
    test asks for the worker: the same planner and plans, without spawning a Python process
    that imports numpy and scipy and measures the map's landmarks again (about 3 CPU-s; the
    worker's own tests are tests/nav/test_plan_process.py)."""
    params = NavigationParams(plan_in_process=plan_in_process) if localize else None
    return NavigatorRobot(
        office, grid, anchors, clock, seed=4, localize=localize, start=start, params=params
    )


async def test_drives_between_desks_with_localization(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    clock = SimClock()
    # The service's robot as it runs: plans in the worker process its start starts.
    async with _robot(
        office,
        office_map,
        office_anchors,
        clock,
        localize=True,
        start="desk_01",
        plan_in_process=True,
    ) as robot:
        result = await robot.move_to("desk_10")
        assert result.place == "desk_10"
        planned = robot.path_distance("desk_01", "desk_10")
        assert planned >= math.hypot(4.0, 7.0)
        assert result.distance_m == pytest.approx(planned, rel=0.15)
        # The clock advanced by the driving time: at least distance / 0.5 m/s.
        assert clock.now() == pytest.approx(result.duration_s)
        assert result.duration_s >= result.distance_m / 0.5
        state = robot.state()
        assert state.place == "desk_10"
        assert not state.moving
        assert state.particles is not None
        assert 0 < len(state.particles) <= 500
        anchor = office_anchors["desk_10"]
        assert math.hypot(state.pose.x - anchor.x, state.pose.y - anchor.y) < 0.15
        true = robot.navigator.base.true_pose
        assert math.hypot(true[0] - anchor.x, true[1] - anchor.y) < 0.15
        assert state.odometer_m == pytest.approx(result.distance_m, abs=1e-3)


async def test_fast_mode_is_kinematic_and_cached(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    clock = SimClock()
    robot = _robot(office, office_map, office_anchors, clock, localize=False, start="meeting_room")
    first = await robot.move_to("print_room")
    expected = robot.path_distance("meeting_room", "print_room")
    assert first.distance_m == pytest.approx(expected, abs=1e-3)
    assert first.duration_s >= expected / 0.5
    tour = ["desk_05", "coffee_corner", "vending_area", "desk_16", "meeting_room"]
    for place in tour:
        result = await robot.move_to(place)
        assert result.place == place
    assert robot.state().particles is None
    assert robot.state().place == "meeting_room"
    assert clock.now() == pytest.approx(robot.navigator.base.time_s)
    # Distances are symmetric, at least the straight line, and the same place is 0.
    for a, b in [("desk_01", "desk_16"), ("print_room", "vending_area")]:
        d_ab, d_ba = robot.path_distance(a, b), robot.path_distance(b, a)
        assert d_ab == pytest.approx(d_ba, rel=0.02)
        straight = math.dist(
            (office_anchors[a].x, office_anchors[a].y), (office_anchors[b].x, office_anchors[b].y)
        )
        assert straight <= d_ab < 1.6 * straight
    assert robot.path_distance("desk_03", "desk_03") == 0.0


async def test_unknown_places_and_missing_anchors(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=False, start="desk_01")
    with pytest.raises(UnreachableError, match="'roof' is not a place on the map"):
        await robot.move_to("roof")
    with pytest.raises(UnreachableError, match="not a place"):
        robot.path_distance("desk_01", "roof")
    partial = {k: v for k, v in office_anchors.items() if k != "kitchenette"}
    with pytest.raises(MapError, match="kitchenette"):
        NavigatorRobot(office, office_map, partial, SimClock())


async def test_anchor_inside_a_wall_is_refused_at_start_up(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    # Issue 18: a bad anchor is found when the robot is built, not when it first goes there.
    moved = dict(office_anchors)
    moved["kitchenette"] = Anchor(29.0, 24.0, 0.0)  # inside the counter
    with pytest.raises(MapError, match=r"^anchor 'kitchenette': \(29.00, 24.00\) is inside"):
        _robot(office, office_map, moved, SimClock(), localize=False, start="desk_01")


async def test_blocked_door_in_fast_mode(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=False, start="desk_09")
    robot.block(3.7, 18.0, 1.0)  # the print room's only door
    with pytest.raises(BlockedError, match="print_room"):
        await robot.move_to("print_room")
    # Other places are still reachable, round the obstacle where needed.
    result = await robot.move_to("coffee_corner")
    assert result.place == "coffee_corner"
    robot.clear_obstacles()
    assert (await robot.move_to("print_room")).place == "print_room"


async def test_driving_round_an_unmapped_obstacle(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=True, start="desk_02")
    robot.block(11.0, 6.2, 0.4)  # on the straight line between desk_02 and desk_04
    result = await robot.move_to("desk_04")
    assert result.place == "desk_04"
    # It saw the obstacle and went round: the true track keeps clear of it.
    track = np.array([s.true_pose[:2] for s in robot.navigator.tracking])
    assert np.hypot(track[:, 0] - 11.0, track[:, 1] - 6.2).min() > 0.4 + 0.15
    assert result.distance_m > 8.05


async def test_blocked_while_driving(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=True, start="desk_09")
    robot.block(3.7, 18.0, 1.0)
    with pytest.raises(BlockedError, match="blocked"):
        await robot.move_to("print_room")
    assert robot.state().place is None
    assert not robot.state().moving


async def test_kidnapped_robot_reports_localization_lost(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=True, start="desk_01")
    robot.navigator.base.teleport(np.array([37.0, 20.5, 0.0]))  # carried off to vending
    with pytest.raises(LocalizationLostError):
        await robot.move_to("desk_03")


async def test_robots_on_the_same_files_share_the_planner(office: Office) -> None:
    first = NavigatorRobot.from_files(office, SimClock(), localize=False)
    second = NavigatorRobot.from_files(office, SimClock(), localize=False)
    assert first.grid is second.grid
    assert first.navigator.planner is second.navigator.planner
    distance = first.path_distance("desk_01", "kitchenette")
    assert second.path_distance("kitchenette", "desk_01") == pytest.approx(distance, rel=0.02)
    with pytest.raises(MapError, match="cannot read map files"):
        NavigatorRobot.from_files(office, SimClock(), map_yaml="/nonexistent/map.yaml")


def _inside_a_wall(grid: OccupancyMap) -> np.ndarray:
    """A pose at the map's occupied cell farthest from any free one (deep in a wall)."""
    from scipy.ndimage import distance_transform_edt

    depth = distance_transform_edt(grid.occupied)
    row, col = np.unravel_index(int(np.argmax(depth)), depth.shape)
    assert depth[row, col] * grid.resolution > 1.0  # no free cell within a metre
    return np.array([*grid.cell_to_world(int(col), int(row)), 0.0])


def test_an_estimate_inside_a_wall_is_localization_lost_not_an_unreachable_goal(
    office: Office, office_map: OccupancyMap, office_anchors: dict[str, Anchor]
) -> None:
    goal = (office_anchors["desk_03"].x, office_anchors["desk_03"].y)
    wall = _inside_a_wall(office_map)
    robot = _robot(office, office_map, office_anchors, SimClock(), localize=True, start="desk_01")
    assert robot.navigator.filter is not None
    robot.navigator.filter.initialize(wall, covariance_diag=(1e-6, 1e-6, 1e-6))
    with pytest.raises(LocalizationLostError, match="inside a wall of the map"):
        robot.navigator.plan(goal)
    # without localization the pose is the truth: a start in a wall is the map's problem
    kinematic = _robot(
        office, office_map, office_anchors, SimClock(), localize=False, start="desk_01"
    )
    kinematic.navigator.base.teleport(wall)
    with pytest.raises(UnreachableError, match=r"start .* is inside an obstacle"):
        kinematic.navigator.plan(goal)
