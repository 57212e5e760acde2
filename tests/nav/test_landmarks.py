"""The planner's landmark bounds: never above a path's cost, so plans stay optimal; kept on
costs that only rose, dropped when a cost falls below them; shared by planners on the same
costs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.sparse.csgraph import dijkstra

from assistantx.nav import landmarks, plan_process
from assistantx.nav.costmap import LETHAL, Costmap, InflationParams
from assistantx.nav.occupancy_map import OCCUPIED, OccupancyMap, load_map
from assistantx.nav.planner import GridPlanner, PlannerParams, costmap_graph
from helpers.maps import REPO, real_map

SLACK = 1.0 / (1 << 22)  # _grid_astar.c's MARK_SLACK


def _costmap(name: str) -> Costmap:
    path = REPO / "maps" / "office.yaml" if name == "office" else real_map(name)
    return Costmap.inflate(load_map(path))


def _reference(costmap: Costmap, source: tuple[int, int]) -> np.ndarray:
    """Scipy's Dijkstra over the planner's graph: the cheapest cost to every cell."""
    graph, ids = costmap_graph(costmap, PlannerParams().cost_penalty)
    dist = dijkstra(graph, indices=int(ids[source]))
    out = np.full(costmap.costs.shape, np.inf)
    out[ids >= 0] = dist[ids[ids >= 0]]
    return out


def _world(costmap: Costmap, cell: tuple[int, int]) -> tuple[float, float]:
    x, y = costmap.grid.cell_to_world(cell[1], cell[0])
    return float(x), float(y)


def test_the_landmark_bound_never_exceeds_the_cheapest_cost() -> None:
    """|d(L, g) - d(L, v)|, less the rounding slack, is at most d(v, g) for every cell v,
    from several goals on tb3_sandbox (whose walls make paths dear, so the bound is tight)."""
    costmap = _costmap("tb3_sandbox")
    planner = GridPlanner(costmap)
    marks = planner.prepare()
    assert marks is not None
    y0, y1, x0, x1 = marks.box
    assert (y1 - y0) * (x1 - x0) < costmap.costs.size / 10  # its free space is a small box
    table = marks.table.astype(np.float64)
    rng = np.random.default_rng(3)
    free = np.argwhere(costmap.costs == 0)
    tight = 0
    for goal in free[rng.integers(0, len(free), 6)]:
        exact = _reference(costmap, (int(goal[0]), int(goal[1])))[y0:y1, x0:x1].ravel()
        there = table[(goal[0] - y0) * (x1 - x0) + goal[1] - x0]
        usable = (table >= 0) & (there >= 0)
        bound = np.where(usable, np.abs(table - there) - (table + there) * SLACK, 0.0).max(axis=1)
        reached = np.isfinite(exact)
        assert (bound[reached] <= exact[reached]).all()
        tight += int((bound[reached] >= 0.99 * exact[reached]).sum())
    assert tight > 1000  # a bound that helps: within 1% of the truth for many cells


@pytest.mark.parametrize("name", ["tb3_sandbox", "depot", "office"])
def test_plans_with_landmarks_cost_what_a_full_dijkstra_says(name: str) -> None:
    costmap = _costmap(name)
    steered = GridPlanner(costmap, PlannerParams(smooth=False))
    plain = GridPlanner(costmap, PlannerParams(smooth=False, landmarks=0))
    assert steered.prepare() is not None
    assert plain.prepare() is None
    rng = np.random.default_rng(17)
    free = np.argwhere(costmap.costs == 0)
    source = tuple(int(v) for v in free[rng.integers(len(free))])
    reference = _reference(costmap, (source[0], source[1]))
    compared = 0
    for cell in free[rng.integers(0, len(free), 12)]:
        expected = reference[cell[0], cell[1]]
        if not math.isfinite(expected):
            continue
        start, goal = _world(costmap, (source[0], source[1])), _world(costmap, (cell[0], cell[1]))
        assert steered.plan(start, goal).cost == pytest.approx(expected, rel=1e-9)
        assert plain.plan(start, goal).cost == pytest.approx(expected, rel=1e-9)
        compared += 1
    assert compared >= 8


def _walled_room() -> Costmap:
    """60 x 60 cells, a wall across the middle (row 30) with a gap at each end."""
    data = np.zeros((60, 60), dtype=np.int8)
    data[30, 6:54] = OCCUPIED
    params = InflationParams(inflation_radius=0.3, cost_scaling_factor=5.0, robot_radius=0.05)
    return Costmap.inflate(OccupancyMap(data, 0.05), params)


def _block(costmap: Costmap, rows: slice, cols: slice) -> tuple[int, int, int, int]:
    costmap.costs[rows, cols] = LETHAL
    return (rows.start, rows.stop, cols.start, cols.stop)


def test_a_layered_planner_keeps_the_maps_landmarks_and_stays_optimal() -> None:
    """Obstacles seen only raise costs: the map's landmarks still bound them, and a plan
    round a new obstacle (one gap closed) costs what a full Dijkstra says."""
    static = _walled_room()
    planner = GridPlanner(static)
    marks = planner.prepare()
    assert marks is not None
    seen = Costmap(static.grid, static.costs.copy(), static.obstacle_distance_m, static.params)
    layered = planner.layered(seen)
    layered.update_window(_block(seen, slice(24, 37), slice(0, 6)))  # the west gap closed
    assert layered.prepare() is marks
    start, goal = (15, 10), (45, 10)
    path = layered.plan(_world(seen, start), _world(seen, goal))
    assert path.cost == pytest.approx(_reference(seen, start)[goal], rel=1e-9)
    assert path.points[:, 0].max() > 54 * 0.05  # round by the east gap


def test_a_cost_falling_below_the_landmarks_drops_them() -> None:
    """Landmarks measured with the west gap closed overstate the costs once it opens again;
    the planner drops them and still finds the short way through the opened gap."""
    closed = _walled_room()
    window = _block(closed, slice(24, 37), slice(0, 6))
    opened_costs = _walled_room().costs
    planner = GridPlanner(closed)
    assert planner.prepare() is not None
    closed.costs[:] = opened_costs  # in place, as the obstacle layer does, then told
    planner.update_window(window)
    assert planner.prepare() is None
    start, goal = (15, 10), (45, 10)
    path = planner.plan(_world(closed, start), _world(closed, goal))
    assert path.cost == pytest.approx(_reference(closed, start)[goal], rel=1e-9)
    assert path.points[:, 0].max() < 30 * 0.05  # through the west gap


def test_a_goal_outside_the_landmarks_component_is_planned_without_them() -> None:
    """Landmarks sit in the largest free component; a plan in a smaller room (every
    landmark distance unreached there) falls back to the octile bound, still optimal."""
    data = np.zeros((60, 60), dtype=np.int8)
    data[40, :] = OCCUPIED  # rows 41.. are a closed room, smaller than the rest
    params = InflationParams(inflation_radius=0.2, cost_scaling_factor=5.0, robot_radius=0.05)
    costmap = Costmap.inflate(OccupancyMap(data, 0.05), params)
    planner = GridPlanner(costmap)
    marks = planner.prepare()
    assert marks is not None
    y0, _, x0, x1 = marks.box
    room = (50 - y0) * (x1 - x0) + np.arange(5, 55) - x0
    assert (marks.table[room] < 0).all()
    start, goal = (50, 5), (55, 54)
    path = planner.plan(_world(costmap, start), _world(costmap, goal))
    assert path.cost == pytest.approx(_reference(costmap, start)[goal], rel=1e-9)


def test_planners_on_the_same_costs_share_one_measurement() -> None:
    first = GridPlanner(_walled_room())
    second = GridPlanner(_walled_room())  # another map object, the same costs
    fewer = GridPlanner(_walled_room(), PlannerParams(landmarks=3))
    assert first.prepare() is second.prepare()
    marks = fewer.prepare()
    assert marks is not None
    assert marks.table.shape[1] == 3


def test_the_planning_worker_gives_layered_costs_the_maps_landmarks() -> None:
    """In the worker a robot's layered costs arrive as a new planner per version; it takes
    the kept map planner's landmarks instead of measuring its own (a few full Dijkstras)."""
    static = _walled_room()
    planner = GridPlanner(static)
    plan_process._worker_planners.clear()
    try:
        plan_process._keep_in_worker(("map", 0), plan_process._payload(planner))
        plan_process._prepare_in_worker(("map", 0))
        kept = plan_process._worker_planners[("map", 0)].marks
        assert kept is not None
        seen = static.costs.copy()
        seen[24:37, 0:6] = LETHAL
        payload = (static.grid, seen, static.params, planner.params, None)
        assert plan_process._planner_from(payload).marks is kept
        lowered = static.costs.copy()
        lowered[30, 20] = 0  # a wall cell gone: below the map's costs
        payload = (static.grid, lowered, static.params, planner.params, None)
        assert plan_process._planner_from(payload).marks is None  # measured on its first plan
    finally:
        plan_process._worker_planners.clear()


def test_no_landmarks_without_a_traversable_cell() -> None:
    costs = np.full((10, 10), LETHAL, dtype=np.uint8)
    assert landmarks.measure_landmarks(costs, 0.05, 2.0, np.zeros((10, 10), np.int32)) is None


def test_a_floor_too_big_for_the_table_gets_fewer_landmarks_or_none() -> None:
    costmap = _walled_room()  # 3,600 cells: 4 bytes a cell a landmark
    components = GridPlanner(costmap, PlannerParams(landmarks=0)).known_components()
    assert components is not None
    cells = costmap.costs.size  # the box is the whole room: free to its edges
    three = landmarks.measure_landmarks(costmap.costs, 0.05, 2.0, components, 8, 4 * cells * 3)
    assert three is not None
    assert three.table.shape == (cells, 3)
    one = landmarks.measure_landmarks(costmap.costs, 0.05, 2.0, components, 8, 4 * cells * 1)
    assert one is None


def test_space_opened_outside_the_searched_box_is_searched_after_the_update() -> None:
    """The search runs on the box round the traversable cells; cells freed outside it (in
    place, then told) widen the box, and a plan into them is found and optimal."""
    data = np.full((80, 80), OCCUPIED, dtype=np.int8)
    data[10:30, 10:30] = 0  # one room: the box is 20 x 20 cells, less the inflation
    params = InflationParams(inflation_radius=0.1, cost_scaling_factor=5.0, robot_radius=0.05)
    costmap = Costmap.inflate(OccupancyMap(data, 0.05), params)
    planner = GridPlanner(costmap)
    marks = planner.prepare()
    assert marks is not None
    assert marks.box[1] <= 30
    start = (20, 20)
    planner.plan(_world(costmap, start), _world(costmap, (25, 25)))  # searched in the box
    costmap.costs[18:22, 28:70] = 0  # a corridor east, out of the box, into new space
    costmap.costs[18:60, 66:70] = 0
    planner.update_window((18, 60, 28, 70))
    goal = (58, 68)
    path = planner.plan(_world(costmap, start), _world(costmap, goal))
    assert path.cost == pytest.approx(_reference(costmap, start)[goal], rel=1e-9)
