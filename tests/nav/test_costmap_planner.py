"""Inflation values (nav2's formula) and the grid planner: optimality, smoothing, failures."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.ndimage import distance_transform_edt
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from assistantx.core.errors import UnreachableError
from assistantx.nav import grid_astar
from assistantx.nav.costmap import (
    INSCRIBED,
    LETHAL,
    NO_INFORMATION,
    Costmap,
    InflationParams,
    capped_distance,
    inflation_cost,
)
from assistantx.nav.occupancy_map import OCCUPIED, UNKNOWN, OccupancyMap, load_map
from assistantx.nav.planner import (
    GridPlanner,
    PlannerParams,
    costmap_graph,
    resample_polyline,
    shortcut,
)
from helpers.maps import REPO, real_map

RES = 0.05


def _grid(height: int, width: int) -> np.ndarray:
    return np.zeros((height, width), dtype=np.int8)


def test_inflation_values_around_one_obstacle() -> None:
    data = _grid(41, 41)
    data[20, 20] = OCCUPIED
    data[0, 0] = UNKNOWN
    params = InflationParams(inflation_radius=0.55, cost_scaling_factor=10.0, robot_radius=0.2)
    costmap = Costmap.inflate(OccupancyMap(data, RES), params)
    row = costmap.costs[20]
    assert row[20] == LETHAL
    assert row[16] == INSCRIBED  # 0.20 m: on the inscribed radius
    # 0.30 m: 252 * exp(-10 * (0.30 - 0.20)) = 92.7 -> 92
    assert row[26] == 92 == math.floor(252 * math.exp(-1.0))
    # 0.55 m: 252 * exp(-3.5) = 7.6 -> 7; 0.60 m: beyond the inflation radius.
    assert row[31] == 7
    assert row[32] == 0
    # Diagonal distance sqrt(2) * 0.25 = 0.354 m -> 252 * exp(-1.536) = 54.3 -> 54.
    assert costmap.costs[25, 25] == 54
    assert costmap.costs[0, 0] == NO_INFORMATION
    assert costmap.cost_at(-1.0, 0.0) == NO_INFORMATION
    # Costs fall monotonically with distance.
    assert np.all(np.diff(row[20:].astype(int)) <= 0)


def test_tiled_distance_equals_the_whole_maps_transform_within_its_reach() -> None:
    """Tiles (512 cells a side) with a halo give the whole map's distances up to the reach,
    across tile borders, and inf beyond; a tile with no obstacle near is all inf."""
    rng = np.random.default_rng(4)
    lethal = np.zeros((1300, 1100), dtype=bool)
    lethal[:500] = rng.random((500, 1100)) < 0.0005  # sparse speckle: long distances
    lethal[700:1000, 300:302] = True  # a wall across a tile border (512)
    full = distance_transform_edt(~lethal) * RES
    reach = 2.0
    capped = capped_distance(lethal, RES, reach)
    near = full <= reach
    np.testing.assert_array_equal(capped[near], full[near])
    assert np.isinf(capped[full > reach + RES]).all()
    assert near.sum() > 100_000 and (~near).sum() > 100_000
    assert np.isinf(capped[1100:, 800:]).all()


def test_inflation_cost_function_and_params() -> None:
    params = InflationParams()
    assert inflation_cost([0.0, 0.1, 0.25, 10.0], params).tolist() == [
        LETHAL,
        INSCRIBED,
        INSCRIBED,
        0,
    ]
    with pytest.raises(ValueError, match="robot_radius"):
        InflationParams(inflation_radius=0.1, robot_radius=0.2)
    with pytest.raises(ValueError, match="cost_scaling_factor"):
        InflationParams(cost_scaling_factor=0)


def _planner(data: np.ndarray, penalty: float = 0.0, smooth: bool = False) -> GridPlanner:
    params = InflationParams(inflation_radius=0.1, cost_scaling_factor=10.0, robot_radius=0.05)
    costmap = Costmap.inflate(OccupancyMap(data, RES), params)
    return GridPlanner(costmap, PlannerParams(cost_penalty=penalty, smooth=smooth))


def _centre(ix: int, iy: int) -> tuple[float, float]:
    return ((ix + 0.5) * RES, (iy + 0.5) * RES)


def test_open_grid_cost_is_the_octile_distance() -> None:
    planner = _planner(_grid(30, 30))
    path = planner.plan(_centre(2, 3), _centre(22, 11))
    # 8 diagonal + 12 straight moves.
    expected = (8 * math.sqrt(2) + 12) * RES
    assert path.cost == pytest.approx(expected)
    assert path.length_m == pytest.approx(expected)
    assert path.grid_cells == 21


def test_path_goes_round_a_wall_through_the_gap() -> None:
    data = _grid(40, 40)
    data[0:35, 20] = OCCUPIED  # wall with a gap at the top (rows 35..39)
    planner = _planner(data, smooth=True)
    start, goal = _centre(10, 5), _centre(30, 5)
    path = planner.plan(start, goal)
    assert path.points[:, 1].max() > 35 * RES  # went through the gap
    # Lower bound: straight lines start -> gap corner -> goal.
    corner = (20.5 * RES, 36.0 * RES)
    assert path.length_m >= math.dist(start, corner) + math.dist(corner, goal) - 0.05
    dense = resample_polyline(path.points, RES / 4)
    ix, iy = planner.costmap.grid.world_to_cell(dense[:, 0], dense[:, 1])
    assert (planner.costmap.costs[iy, ix] < INSCRIBED).all()


def test_smoothing_shortens_without_touching_obstacles() -> None:
    data = _grid(60, 60)
    data[20:40, 25:35] = OCCUPIED
    raw = _planner(data, penalty=2.0).plan(_centre(5, 7), _centre(55, 50))
    smooth = _planner(data, penalty=2.0, smooth=True).plan(_centre(5, 7), _centre(55, 50))
    assert smooth.length_m < raw.length_m
    assert len(smooth.points) < len(raw.points) / 5
    assert smooth.cost == raw.cost  # the cost is the optimum of the grid search


def test_cost_penalty_keeps_away_from_walls() -> None:
    data = _grid(30, 60)
    data[0:12, 30] = OCCUPIED  # a wall stub from the bottom
    params = InflationParams(inflation_radius=1.0, cost_scaling_factor=3.0, robot_radius=0.05)
    costmap = Costmap.inflate(OccupancyMap(data, RES), params)
    near = GridPlanner(costmap, PlannerParams(cost_penalty=0.0, smooth=False))
    far = GridPlanner(costmap, PlannerParams(cost_penalty=5.0, smooth=False))
    a, b = _centre(5, 5), _centre(55, 5)
    assert far.plan(a, b).points[:, 1].max() > near.plan(a, b).points[:, 1].max()


@pytest.mark.parametrize(
    ("goal", "reason"),
    [
        ((100.0, 1.0), "off the map"),
        ((1.0 + 0.025, 0.5 + 0.025), "inside an obstacle"),
        ((1.0 + 0.025 + 0.05, 0.5 + 0.025), "too close to an obstacle"),
        ((0.275, 1.275), "cut off"),
        ((0.525, 1.525), "unknown space"),
    ],
)
def test_unreachable_goals(goal: tuple[float, float], reason: str) -> None:
    data = _grid(40, 40)
    data[10, 20] = OCCUPIED
    data[20:31, 0:12] = OCCUPIED  # a closed box ...
    data[22:29, 1:11] = 0  # ... with free space inside (cell (5, 25) at x 0.275, y 1.275)
    data[30, 10] = UNKNOWN
    planner = _planner(data)
    with pytest.raises(UnreachableError, match=reason):
        planner.plan(_centre(30, 30), goal)


def test_start_slightly_inside_the_inscribed_zone_snaps_out() -> None:
    data = _grid(30, 30)
    data[:, 15] = OCCUPIED
    planner = _planner(data)
    path = planner.plan(_centre(14, 5), _centre(5, 5))  # start touches the wall
    assert path.length_m == pytest.approx(9 * RES, abs=1e-9)
    with pytest.raises(UnreachableError, match=r"start .* is off the map"):
        planner.plan((-1.0, 0.0), _centre(5, 5))


def test_plan_many_matches_single_queries(office_planner: GridPlanner) -> None:
    start, goals = (5.0, 6.0), [(9.0, 6.0), (37.0, 20.5), (0.05, 0.05)]
    many = office_planner.plan_many(start, goals)
    assert many[2] is None  # inside the outer wall
    for goal, path in zip(goals[:2], many[:2], strict=True):
        assert path is not None
        single = office_planner.plan(start, goal)
        assert path.cost == pytest.approx(single.cost)
        assert path.length_m == pytest.approx(single.length_m)


def _full_graph_costs(costmap: Costmap, source: tuple[int, int], penalty: float) -> np.ndarray:
    """The previous planner's algorithm, as the reference: one graph over every traversable
    cell (COO-built, both directions) and an unbounded Dijkstra; the cost to every cell."""
    traversable = costmap.traversable
    height, width = traversable.shape
    node = np.full(traversable.shape, -1, dtype=np.int64)
    node[traversable] = np.arange(int(traversable.sum()))
    cost = costmap.costs.astype(np.float64)
    rows, cols, weights = [], [], []
    for dy, dx in ((0, 1), (1, 0), (1, 1), (1, -1)):
        ys, ys2 = slice(0, height - dy), slice(dy, height)
        xs, xs2 = slice(max(0, -dx), width - max(0, dx)), slice(max(0, dx), width + min(0, dx))
        ok = traversable[ys, xs] & traversable[ys2, xs2]
        if dy and dx:
            ok &= traversable[ys2, xs] & traversable[ys, xs2]
        mean = (cost[ys, xs] + cost[ys2, xs2])[ok] / 2
        rows.append(node[ys, xs][ok])
        cols.append(node[ys2, xs2][ok])
        weights.append(costmap.grid.resolution * math.hypot(dy, dx) * (1 + penalty * mean / 252))
    r, c, w = np.concatenate(rows), np.concatenate(cols), np.concatenate(weights)
    n = int(traversable.sum())
    graph = csr_matrix((np.r_[w, w], (np.r_[r, c], np.r_[c, r])), shape=(n, n))
    dist = dijkstra(graph, indices=int(node[source]))
    out = np.full(traversable.shape, np.inf)
    out[traversable] = dist
    return out


@pytest.mark.parametrize("compiled", [True, False])
def test_a_maze_path_far_longer_than_the_map_is_found_and_optimal(compiled: bool) -> None:
    """A serpentine: the only way is many times the map's diagonal, beyond every bounded
    region; the last search is unbounded and still finds the optimum."""
    data = _grid(90, 90)
    for row in range(6, 90, 6):
        data[row, :] = OCCUPIED
        if (row // 6) % 2:
            data[row, 84:] = 0  # gap at the east end
        else:
            data[row, :6] = 0  # gap at the west end
    planner = _planner(data)
    planner.params = PlannerParams(cost_penalty=0.0, smooth=False, compiled_search=compiled)
    start, goal = _centre(2, 2), _centre(2, 87)
    path = planner.plan(start, goal)
    diagonal = math.hypot(90, 90) * RES
    assert path.cost > 3 * diagonal
    reference = _full_graph_costs(planner.costmap, (2, 2), 0.0)
    assert path.cost == pytest.approx(reference[87, 2], rel=1e-9)


def test_the_compiled_search_is_built_with_the_package() -> None:
    """Without it every plan falls back to the bounded Dijkstra (several times slower)."""
    assert grid_astar.available()


@pytest.mark.parametrize(
    ("name", "compiled"),
    [("depot", True), ("tb3_sandbox", True), ("office", True), ("depot", False)],
)
def test_plan_costs_equal_a_full_graph_dijkstra_on_real_maps(name: str, compiled: bool) -> None:
    """Both searches (A* in C, and the ellipse-bounded Dijkstra it falls back to) find the
    same optimal costs as one Dijkstra over the whole free space (the maze test above covers
    paths far longer than the straight line)."""
    path_of_map = REPO / "maps" / "office.yaml" if name == "office" else real_map(name)
    grid = load_map(path_of_map)
    costmap = Costmap.inflate(grid)
    planner = GridPlanner(costmap, PlannerParams(smooth=False, compiled_search=compiled))
    rng = np.random.default_rng(11)
    free = np.argwhere(costmap.costs == 0)
    source = tuple(int(v) for v in free[rng.integers(len(free))])
    reference = _full_graph_costs(costmap, (source[0], source[1]), PlannerParams().cost_penalty)
    start = grid.cell_to_world(source[1], source[0])
    for cell in free[rng.integers(0, len(free), 12)]:
        if not math.isfinite(reference[cell[0], cell[1]]):
            continue  # another component: test_unreachable_goals covers those
        goal = grid.cell_to_world(cell[1], cell[0])
        path = planner.plan((float(start[0]), float(start[1])), (float(goal[0]), float(goal[1])))
        assert path.cost == pytest.approx(reference[cell[0], cell[1]], rel=1e-9)


def test_the_planners_graph_is_the_reference_graph(office_planner: GridPlanner) -> None:
    """``costmap_graph`` (what the bench's full Dijkstra runs on) is the graph the planner
    searches: its Dijkstra gives the reference costs."""
    costmap = office_planner.costmap
    graph, ids = costmap_graph(costmap, PlannerParams().cost_penalty)
    source = (250, 100)
    assert ids[source] >= 0
    dist = dijkstra(graph, indices=int(ids[source]))
    reference = _full_graph_costs(costmap, source, PlannerParams().cost_penalty)
    traversable = costmap.traversable
    assert np.allclose(dist, reference[traversable], rtol=1e-12, equal_nan=False)


@pytest.mark.parametrize("yaw", [0.0, 0.4])
def test_the_compiled_smoothing_keeps_the_waypoints_the_python_shortcut_keeps(
    yaw: float,
) -> None:
    """A compiled plan smooths its path in C: the same waypoints, to the last bit, as
    ``shortcut`` over the same unsmoothed path (on tb3_sandbox's pillars, with and without
    a rotated map origin)."""
    base = load_map(real_map("tb3_sandbox"))
    grid = OccupancyMap(base.data, base.resolution, base.origin_x, base.origin_y, yaw)
    costmap = Costmap.inflate(grid)
    raw = GridPlanner(costmap, PlannerParams(smooth=False))
    smoothed = GridPlanner(costmap, PlannerParams())
    rng = np.random.default_rng(5)
    free = np.argwhere(costmap.costs < 200)
    compared = 0
    for _ in range(40):
        a, b = free[rng.integers(0, len(free), 2)]
        start = tuple(float(v) + 0.013 for v in grid.cell_to_world(a[1], a[0]))
        goal = tuple(float(v) - 0.01 for v in grid.cell_to_world(b[1], b[0]))
        try:
            unsmoothed = raw.plan((start[0], start[1]), (goal[0], goal[1]))
        except UnreachableError:
            continue
        path = smoothed.plan((start[0], start[1]), (goal[0], goal[1]))
        expected = shortcut(unsmoothed.points, costmap)
        assert np.array_equal(path.points, expected)
        assert path.cost == unsmoothed.cost
        assert path.grid_cells == unsmoothed.grid_cells
        compared += len(unsmoothed.points) > 2
    assert compared >= 20
