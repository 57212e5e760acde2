"""Planning in a worker process (issue 18): the same paths as in-process, obstacles seen
since the last plan reach the worker, and the planner's reasons come back as they are."""

from __future__ import annotations

import logging
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from assistantx.core.errors import UnreachableError
from assistantx.nav import disk_cache
from assistantx.nav.costmap import Costmap, update_obstacles
from assistantx.nav.occupancy_map import FREE, OCCUPIED, OccupancyMap
from assistantx.nav.plan_process import PlanProcess
from assistantx.nav.planner import GridPlanner

RES = 0.05


@pytest.fixture(scope="module")
def worker() -> Iterator[PlanProcess]:
    process = PlanProcess()
    yield process
    process.close()


def _hall() -> OccupancyMap:
    """A 6 x 4 m hall, walled round, with a wall across it that has one 1 m door."""
    data = np.full((80, 120), FREE, dtype=np.int8)
    data[[0, -1], :] = OCCUPIED
    data[:, [0, -1]] = OCCUPIED
    data[:, 60:62] = OCCUPIED
    data[30:50, 60:62] = FREE  # the door
    return OccupancyMap(data, RES)


def test_worker_paths_equal_in_process_paths(worker: PlanProcess) -> None:
    planner = GridPlanner(Costmap.inflate(_hall()))
    for start, goal in [((0.8, 0.8), (5.2, 3.2)), ((5.0, 0.5), (0.6, 3.4))]:
        here, there = planner.plan(start, goal), worker.plan(planner, start, goal)
        assert there.cost == pytest.approx(here.cost, rel=1e-12)
        np.testing.assert_allclose(there.points, here.points)


def test_obstacles_seen_after_the_first_plan_reach_the_worker(worker: PlanProcess) -> None:
    static = Costmap.inflate(_hall())
    layered = Costmap(static.grid, static.costs.copy(), static.obstacle_distance_m, static.params)
    planner = GridPlanner(static).layered(layered)
    start, goal = (1.0, 2.0), (5.0, 2.0)
    assert worker.plan(planner, start, goal).length_m < 4.5  # through the door
    # A box now fills the door: the costs change in place and the version moves on.
    door = np.array([y * static.grid.width + x for y in range(30, 50) for x in range(58, 64)])
    window = update_obstacles(static, layered, door, door)
    assert window is not None
    planner.update_window(window)
    with pytest.raises(UnreachableError, match="cut off"):
        worker.plan(planner, start, goal)


def test_the_worker_raises_the_planners_reason(worker: PlanProcess) -> None:
    planner = GridPlanner(Costmap.inflate(_hall()))
    with pytest.raises(UnreachableError, match=r"goal \(3\.05, 0\.80\) is inside an obstacle"):
        worker.plan(planner, (1.0, 2.0), (3.05, 0.8))
    with pytest.raises(UnreachableError, match="off the map"):
        worker.plan(planner, (1.0, 2.0), (30.0, 2.0))


def test_a_warmed_worker_measures_the_landmarks_into_the_map_cache(tmp_path: Path) -> None:
    """The worker keeps the map cache its parent names, and measures a warmed planner's
    landmarks before its first plan (a second start on the map reads them)."""
    cache = tmp_path / "cache"
    disk_cache.use_directory(cache)
    process = PlanProcess()
    try:
        hall = _hall()
        hall.data[5, 5] = OCCUPIED  # costs no other test measures (no landmarks in memory)
        planner = GridPlanner(Costmap.inflate(hall))
        process.warm(planner)
        path = process.plan(planner, (1.0, 2.0), (5.0, 2.0))
        assert len(list(cache.glob("planner-landmarks-*.npy"))) == 1  # the worker's
        assert planner.marks is None  # none measured here
        assert path.cost == pytest.approx(planner.plan((1.0, 2.0), (5.0, 2.0)).cost)
    finally:
        process.close()
        disk_cache.use_directory(None)


def test_a_stop_ends_a_worker_measuring_landmarks_and_keeps_nothing_half_made(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    """Landmarks are only a head start for the first plan: a stop while the worker measures
    them (8 full Dijkstras on this 60 x 60 m floor, seconds) ends the worker rather than
    waiting for them, and leaves no table, whole or partial, in the map cache."""
    cache = tmp_path / "cache"
    disk_cache.use_directory(cache)
    process = PlanProcess()
    try:
        floor = np.full((1200, 1200), FREE, dtype=np.int8)
        floor[[0, -1], :] = floor[:, [0, -1]] = OCCUPIED
        planner = GridPlanner(Costmap.inflate(OccupancyMap(floor, RES)))
        process.warm(planner)
        with caplog.at_level(logging.INFO, logger="assistantx.nav.plan_process"):
            process.close()
        assert "ended the planning worker while it measured landmarks" in caplog.text
        assert "could not prepare" not in caplog.text  # the stop is no failure
        assert list(cache.glob("planner-landmarks-*")) == []
        assert list(cache.glob(".*.tmp")) == []
    finally:
        process.close()
        disk_cache.use_directory(None)
