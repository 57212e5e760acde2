"""One world for sensor and filter (issue 18): unknown space and the map edge give max-range
readings, which AMCL skips; the obstacle layer marks what the map lacks and clears it again
by ray tracing and decay; the costmap and planner update incrementally."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistantx.core.errors import BlockedError
from assistantx.nav.amcl import AmclParams, LikelihoodField
from assistantx.nav.costmap import Costmap, update_obstacles
from assistantx.nav.lidar import Lidar, LidarParams
from assistantx.nav.navigation import Navigator
from assistantx.nav.obstacle_layer import ObstacleLayer, ObstacleLayerParams
from assistantx.nav.occupancy_map import FREE, OCCUPIED, UNKNOWN, OccupancyMap
from assistantx.nav.planner import GridPlanner

RES = 0.05


def _slam_like_map() -> OccupancyMap:
    """A 10 x 6 m free hall walled on the south and west only; north of it lies unknown
    space (a laser shadow), and to the east the map simply ends."""
    data = np.full((160, 200), UNKNOWN, dtype=np.int8)
    data[0:120, :] = FREE
    data[0:2, :] = OCCUPIED  # south wall
    data[:120, 0:2] = OCCUPIED  # west wall
    data[40:50, 60:70] = OCCUPIED  # a pillar
    return OccupancyMap(data, RES, -1.0, -1.0)


def test_unknown_space_and_the_map_edge_are_max_range_readings() -> None:
    grid = _slam_like_map()
    lidar = Lidar(grid, LidarParams(range_noise_std_m=0.0))
    pose = np.array([4.0, 2.0, 0.0])
    scan = lidar.scan(pose, np.random.default_rng(0))
    returned = scan.ranges < scan.range_max
    # Beams towards the shadow (north) and the edge (east) see nothing ...
    north = np.abs(scan.angles - math.pi / 2) < 0.3
    east = np.abs(scan.angles) < 0.2
    assert not returned[north].any() and not returned[east].any()
    # ... and every beam that did return ends on an occupied cell, where AMCL's likelihood
    # field puts its walls: sensor and filter describe the same world.
    field = LikelihoodField(grid, AmclParams())
    distances = field.endpoint_distances(pose, scan.ranges[returned], scan.angles[returned])
    assert returned.sum() > 20
    assert distances.max() < 0.06


def test_driving_beside_a_laser_shadow_sees_no_false_obstacles() -> None:
    grid = _slam_like_map()
    nav = Navigator(grid, np.array([1.0, 4.5, 0.0]), np.random.default_rng(3))
    path = nav.plan((8.0, 4.5))
    for _ in nav.follow(path, 0.0):
        pass
    true = nav.base.true_pose
    assert math.hypot(true[0] - 8.0, true[1] - 4.5) < 0.1
    assert len(nav.obstacles) == 0
    errors = [math.dist(s.true_pose[:2], s.estimate[:2]) for s in nav.tracking]
    assert max(errors) < 0.1


def _room() -> OccupancyMap:
    data = np.zeros((100, 100), dtype=np.int8)
    data[0, :] = data[-1, :] = data[:, 0] = data[:, -1] = OCCUPIED
    return OccupancyMap(data, RES)


def _layer(grid: OccupancyMap, **params: float) -> ObstacleLayer:
    return ObstacleLayer(
        grid, Costmap.inflate(grid).obstacle_distance_m, ObstacleLayerParams(**params)
    )


def _with_box(grid: OccupancyMap, x0: int, x1: int, y0: int, y1: int) -> OccupancyMap:
    data = grid.data.copy()
    data[y0:y1, x0:x1] = OCCUPIED
    return grid.with_data(data)


def test_obstacle_layer_marks_then_clears_a_departed_obstacle_by_ray_tracing() -> None:
    grid = _room()
    layer = _layer(grid)
    pose = np.array([1.0, 2.5, 0.0])
    rng = np.random.default_rng(0)
    lidar = Lidar(_with_box(grid, 40, 42, 45, 55), LidarParams(range_noise_std_m=0.0))
    changed = layer.update(pose, lidar.scan(pose, rng), now_s=0.0)
    assert len(layer) > 0 and changed.size == len(layer)
    marked_x, _ = grid.cell_to_world(layer.marked % grid.width, layer.marked // grid.width)
    assert np.all(np.abs(marked_x - 2.0) < 0.1)  # the box's near face, nothing of the walls
    lidar.set_world(grid)  # the box is taken away
    cleared = layer.update(pose, lidar.scan(pose, rng), now_s=1.0)
    assert len(layer) == 0
    assert set(cleared.tolist()) == set(changed.tolist())


def test_obstacle_layer_marks_decay_when_not_seen_again() -> None:
    grid = _room()
    layer = _layer(grid, decay_s=10.0)
    pose = np.array([1.0, 2.5, 0.0])
    lidar = Lidar(_with_box(grid, 40, 42, 45, 55), LidarParams(range_noise_std_m=0.0))
    layer.update(pose, lidar.scan(pose, np.random.default_rng(0)), now_s=0.0)
    assert len(layer) > 0
    assert layer.expire(9.0).size == 0 and len(layer) > 0
    assert layer.expire(10.5).size > 0 and len(layer) == 0


def test_incremental_costmap_and_planner_equal_a_full_rebuild() -> None:
    grid = _room()
    static = Costmap.inflate(grid)
    layered = Costmap(static.grid, static.costs.copy(), static.obstacle_distance_m, static.params)
    map_planner = GridPlanner(static)
    planner = map_planner.layered(layered)
    rng = np.random.default_rng(5)
    marked = np.unique(rng.integers(20, 80, 30) * grid.width + rng.integers(20, 80, 30))
    window = update_obstacles(static, layered, marked, marked)
    assert window is not None
    planner.update_window(window)
    data = grid.data.copy()
    data.ravel()[marked] = OCCUPIED
    full = Costmap.inflate(grid.with_data(data))
    np.testing.assert_array_equal(layered.costs, full.costs)
    rebuilt = GridPlanner(full)
    for start, goal in [((0.5, 0.5), (4.4, 4.4)), ((0.5, 4.4), (4.4, 0.6))]:
        a, b = planner.plan(start, goal), rebuilt.plan(start, goal)
        assert a.cost == pytest.approx(b.cost, rel=1e-9)
    # The shared map planner is untouched.
    assert map_planner.plan((0.5, 0.5), (4.4, 4.4)).cost < planner.plan((0.5, 0.5), (4.4, 4.4)).cost


def test_a_false_obstacle_does_not_block_for_ever() -> None:
    grid = _room()
    nav = Navigator(grid, np.array([0.6, 2.5, 0.0]), np.random.default_rng(2))
    # Something stands across the whole room in front of the goal: the robot is blocked.
    nav.set_world(_with_box(grid, 50, 52, 1, 99))
    with pytest.raises(BlockedError, match="block"):
        for _ in nav.follow(nav.plan((4.0, 2.5)), 0.0):
            pass
    assert len(nav.obstacles) > 0
    # It goes away; the next plan looks round first, the beams clear the marks, and the
    # robot gets there (without clearing it would be refused again, for ever).
    nav.set_world(grid)
    for _ in nav.follow(nav.plan((4.0, 2.5)), 0.0):
        pass
    assert math.hypot(nav.base.true_pose[0] - 4.0, nav.base.true_pose[1] - 2.5) < 0.15
    assert len(nav.obstacles) == 0
