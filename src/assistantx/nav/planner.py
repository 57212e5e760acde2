"""A grid planner on an inflated costmap: exact Dijkstra inside an ellipse, then smoothing.

Cells whose cost is below INSCRIBED are nodes, 8-connected (diagonals only where both side
cells are traversable, so paths never cut a corner). An edge from u to v weighs
``length_m * (1 + cost_penalty * (c_u + c_v) / 2 / 252)``, the cost term of nav2's Smac
planner: the path keeps away from walls where there is room.

A query runs A* over the whole grid in C (``grid_astar``). Its heuristic is the larger of
the octile distance (it never overestimates, since every edge weighs at least its grid
length) and the landmark bound (``landmarks``: a few full Dijkstras measured once per map, a
far closer bound where walls make paths dearer than the straight line); both are lower
bounds, so the path is optimal. Set-up is the costmap, a 4-connected labelling, which tells
an unreachable goal at once (without corner cutting, 8-connected moves join exactly the cells
that 4-connected ones do), and the landmarks (both kept in the map cache).

Where the compiled search was not built (no C compiler at install), a query builds the graph
only over the cells p with ``oct(s, p) + oct(p, g) <= L`` (an ellipse-like region round
start s and goal g) and runs scipy's Dijkstra there: a path found with cost <= L never left
that region, so it is optimal over the whole map; otherwise L grows (x1.4) and it repeats.

The grid path is then shortened by line-of-sight shortcuts that never pass closer to an
obstacle than the grid path did over the same stretch (in C with the compiled search, the
same waypoints), and resampled for the controller.
"""

from __future__ import annotations

import itertools
import logging
import math
import uuid
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
import numpy.typing as npt

from assistantx.core.errors import UnreachableError
from assistantx.nav import disk_cache, grid_astar, map_transforms
from assistantx.nav.costmap import INSCRIBED, LETHAL, NO_INFORMATION, Costmap
from assistantx.nav.landmarks import DEFAULT_COUNT, Landmarks, measure_landmarks

# scipy is imported where it is used: a start needs none of it (scipy.ndimage alone is about
# a third of a CPU-second; the components are nav.map_transforms', in C).
if TYPE_CHECKING:
    from scipy.sparse import csr_matrix

logger = logging.getLogger(__name__)


class StartInObstacleError(UnreachableError):
    """The start is inside an obstacle (no free cell within ``start_snap_m``): on the map
    alone, a robot that believes it is there has lost where it is."""


@dataclass(frozen=True)
class PlannerParams:
    cost_penalty: float = 2.0
    start_snap_m: float = 0.5  # a start inside the inscribed zone snaps to free space this near
    smooth: bool = True
    # A* in C where it was built; False: scipy's bounded Dijkstra (the fallback), same costs
    compiled_search: bool = True
    # landmarks steering the compiled A* (0: the octile distance alone; fewer on a floor too
    # big for their table, see landmarks.py); same paths, fewer cells searched, for a set-up
    # of this many full Dijkstras
    landmarks: int = DEFAULT_COUNT


@dataclass(frozen=True)
class Path:
    """A planned path: waypoints in metres, its length (m) and its cost (weighted metres)."""

    points: npt.NDArray[np.float64]  # (n, 2)
    length_m: float
    cost: float
    grid_cells: int

    def resampled(self, spacing_m: float = 0.1) -> npt.NDArray[np.float64]:
        return resample_polyline(self.points, spacing_m)


def _components(traversable: npt.NDArray[np.bool_]) -> npt.NDArray[np.int32]:
    """Each traversable cell's connected component (cells sharing an edge), 0 elsewhere: two
    cells with different labels have no path between them. Kept in the map cache for the
    map's own planner: on a big floor it is a fair part of the set-up."""
    return map_transforms.components(traversable)


class GridPlanner:
    def __init__(
        self,
        costmap: Costmap,
        params: PlannerParams | None = None,
        *,
        components: npt.NDArray[np.int32] | None = None,
        marks: Landmarks | Literal["measure"] | None = "measure",
    ) -> None:
        """``components``: the traversable cells' labels when the caller has them already
        (the planning worker gets them with the costs); else read from the map cache or
        computed. ``marks``: the landmarks to steer by (they must bound these costs), None
        for none; by default measured on the first compiled plan or ``prepare`` (a few full
        Dijkstras: a planner that never plans, or plans in the worker, never pays them)."""
        self.costmap = costmap
        self.params = params or PlannerParams()
        # Who this planner is and which costs it plans on, for a worker process that keeps
        # planners it was sent (plan_process): update_window bumps the version.
        self.token = uuid.uuid4().hex
        self.version = 0
        self._labels: npt.NDArray[np.int32] | None = None
        # For snapping a start that strayed into the inscribed zone back to the nearest
        # traversable cell: made on first need (an EDT with indices is costly on big maps).
        self._nearest_free: npt.NDArray[np.intp] | None = None
        self._frame: grid_astar.MapFrame | None = None  # for the compiled smoothing
        if components is None:
            traversable = costmap.traversable
            components = disk_cache.cached_array(
                "traversable-components",
                (traversable.shape, np.packbits(traversable).tobytes()),
                lambda: _components(traversable),
                mapped=True,  # read a few labels at a time (anchors, a plan's ends)
            )
        self._labels = components
        self._marks: Landmarks | Literal["measure"] | None = marks
        self._base: GridPlanner | None = None  # a layered planner's map planner
        self._box: _Box | None = None  # the costs the compiled search runs on

    def _map_frame(self) -> grid_astar.MapFrame:
        if self._frame is None:
            self._frame = grid_astar.MapFrame(self.costmap.grid)
        return self._frame

    def layered(self, costmap: Costmap) -> GridPlanner:
        """A planner on ``costmap`` (the map's costs plus obstacles seen, never lower)."""
        other = GridPlanner.__new__(GridPlanner)
        other.costmap, other.params = costmap, self.params
        other._labels, other._nearest_free, other._frame = None, None, None
        other.token, other.version = uuid.uuid4().hex, 0
        # The map's landmarks stay lower bounds on costs never below the map's: taken from
        # this planner when first needed (checked then).
        other._marks, other._base, other._box = "measure", self, None
        return other

    def update_window(self, window: tuple[int, int, int, int]) -> None:
        """The costs in ``window`` changed (in place): forget what was derived from them."""
        # The whole labelling is redone on next need (one pass, ~linear); the landmarks are
        # kept while no cost fell below those they were measured on (obstacles seen only add).
        self._labels = None
        self._nearest_free = None
        self._box = None
        marks = self._marks
        if isinstance(marks, Landmarks) and not marks.bounds(self.costmap.costs, window):
            logger.info("costs fell below the planner's landmarks; planning without them")
            self._marks = None
        self.version += 1

    def known_components(self) -> npt.NDArray[np.int32] | None:
        """The component labels when they are made for the current costs, else None."""
        return self._labels

    @property
    def marks(self) -> Landmarks | None:
        """The landmarks this planner steers by, if it has them yet (``prepare``)."""
        return self._marks if isinstance(self._marks, Landmarks) else None

    def prepare(self) -> Landmarks | None:
        """The landmarks to steer by, measured now if not yet (the map cache and the last
        ones measured in this process are looked up first); None when it plans without."""
        if not isinstance(self._marks, str):
            return self._marks
        marks = None
        if self.params.compiled_search and self.params.landmarks > 0 and grid_astar.available():
            costs = self.costmap.costs
            if self._base is not None:  # a layered planner: the map's, where they still hold
                marks = self._base.prepare()
                if marks is not None and not marks.bounds(costs):
                    marks = None
            else:
                res, penalty = self.costmap.grid.resolution, self.params.cost_penalty
                labels, count = self._component_labels(), self.params.landmarks
                marks = measure_landmarks(costs, res, penalty, labels, count)
        self._marks = marks
        return marks

    def _search_box(self) -> _Box:
        """The costs the compiled search runs on: the box round the traversable cells (the
        landmarks' box when steered by them), copied once per version of the costs."""
        if self._box is None:
            marks = self.prepare()
            costs = self.costmap.costs
            y0, y1, x0, x1 = grid_astar.traversable_box(costs) if marks is None else marks.box
            whole = (y0, y1, x0, x1) == (0, costs.shape[0], 0, costs.shape[1])
            inside = costs if whole else np.ascontiguousarray(costs[y0:y1, x0:x1])
            self._box = _Box(
                inside,
                (y0, x0, costs.shape[0], costs.shape[1]),
                _NO_MARKS if marks is None else marks.marks,
            )
        return self._box

    def _component_labels(self) -> npt.NDArray[np.int32]:
        if self._labels is None:
            self._labels = _components(self.costmap.traversable)
        return self._labels

    # -- queries ---------------------------------------------------------------------------
    def plan(self, start: tuple[float, float], goal: tuple[float, float]) -> Path:
        """Plan from start to goal (world metres); raise UnreachableError with the reason."""
        goal_cell = self._goal_cell(goal)
        start_cell = self._start_cell(start)
        if start_cell == goal_cell:
            return self._make_path(np.asarray([start_cell]), 0.0, start, goal)
        labels = self._component_labels()
        if labels[start_cell] != labels[goal_cell]:
            raise UnreachableError(f"goal {_fmt(goal)} is cut off from start {_fmt(start)}")
        res = self.costmap.grid.resolution
        if self.params.compiled_search and grid_astar.available():
            ends = (start[0], start[1], goal[0], goal[1])
            box = self._search_box()
            row0, col0 = box.corner[0], box.corner[1]
            planned = grid_astar.plan(
                box.costs,
                res,
                self.params.cost_penalty,
                (start_cell[0] - row0, start_cell[1] - col0),
                (goal_cell[0] - row0, goal_cell[1] - col0),
                (self._map_frame(), ends) if self.params.smooth else None,
                box.marks,
                box.corner,
            )
            if planned is None:  # cannot happen within one component; kept as a guard
                raise UnreachableError(f"goal {_fmt(goal)} is cut off from start {_fmt(start)}")
            return self._compiled_path(planned, start, goal)
        straight = float(_octile(start_cell[0] - goal_cell[0], start_cell[1] - goal_cell[1])) * res
        # Path costs run a few percent above the straight line in open space; start just
        # above that and widen. Once the region holds the whole map (no cell is farther
        # than ``whole``), search it without a bound: a maze's path may be far longer.
        height, width = self.costmap.costs.shape
        whole = 3.0 * math.hypot(height, width) * res
        limit = 1.1 * straight + 1.0
        while limit < whole:
            found = self._search(start_cell, goal_cell, limit, limit)
            if found is not None:
                return self._make_path(found[0], found[1], start, goal)
            limit *= 1.4
        found = self._search(start_cell, goal_cell, whole, math.inf)
        if found is None:  # cannot happen within one component; kept as a guard
            raise UnreachableError(f"goal {_fmt(goal)} is cut off from start {_fmt(start)}")
        return self._make_path(found[0], found[1], start, goal)

    def plan_many(
        self, start: tuple[float, float], goals: Sequence[tuple[float, float]]
    ) -> list[Path | None]:
        """Paths from one start to many goals (None: unreachable)."""
        paths: list[Path | None] = []
        for goal in goals:
            try:
                paths.append(self.plan(start, goal))
            except UnreachableError:
                paths.append(None)
        return paths

    def _search(
        self, start: tuple[int, int], goal: tuple[int, int], region_m: float, limit_m: float
    ) -> tuple[npt.NDArray[np.intp], float] | None:
        """Dijkstra over the traversable cells with ``oct(s,p) + oct(p,g) <= region_m``;
        the optimal (cells, cost) if its cost is within ``limit_m``, else None."""
        costs = self.costmap.costs
        height, width = costs.shape
        res = self.costmap.grid.resolution
        reach = region_m / res  # in cells
        (sy, sx), (gy, gx) = start, goal
        # A cell beyond the foci's box by e along x has oct(s,p) + oct(p,g) >= 2e + |dx|.
        my = max(0.0, (reach - abs(sy - gy)) / 2)
        mx = max(0.0, (reach - abs(sx - gx)) / 2)
        y0, y1 = max(0, int(min(sy, gy) - my)), min(height, int(max(sy, gy) + my) + 1)
        x0, x1 = max(0, int(min(sx, gx) - mx)), min(width, int(max(sx, gx) + mx) + 1)
        block = costs[y0:y1, x0:x1]
        traversable = block < INSCRIBED
        ys = np.arange(y0, y1, dtype=np.float32)[:, None]
        xs = np.arange(x0, x1, dtype=np.float32)[None, :]
        inside = _octile(ys - sy, xs - sx) + _octile(ys - gy, xs - gx) <= reach + 1e-3
        nodes = traversable & inside
        del inside
        ids = np.full(block.shape, -1, dtype=np.int32)
        count = int(nodes.sum())
        ids[nodes] = np.arange(count, dtype=np.int32)
        graph = _graph(ids, nodes, traversable, block, res, self.params.cost_penalty)
        source, target = int(ids[sy - y0, sx - x0]), int(ids[gy - y0, gx - x0])
        from scipy.sparse.csgraph import dijkstra

        dist, pred = dijkstra(graph, indices=source, return_predecessors=True, limit=limit_m)
        cost = float(dist[target])
        if not (cost <= limit_m and math.isfinite(cost)):
            return None
        path_nodes = _walk_back(pred, target)
        cells = np.argwhere(nodes)[path_nodes] + (y0, x0)
        return cells, cost

    # -- helpers ---------------------------------------------------------------------------
    def _cell(self, point: tuple[float, float], role: str) -> tuple[int, int]:
        """The (row, col) cell under a world point: ``grid.world_to_cell`` for one point, in
        plain floats (numpy's per-call cost on scalars was a tenth of a small plan)."""
        grid = self.costmap.grid
        dx, dy = float(point[0]) - grid.origin_x, float(point[1]) - grid.origin_y
        if grid.origin_yaw != 0.0:
            c, s = math.cos(grid.origin_yaw), math.sin(grid.origin_yaw)
            dx, dy = c * dx + s * dy, -s * dx + c * dy
        fx, fy = dx / grid.resolution, dy / grid.resolution
        height, width = self.costmap.costs.shape
        if not (math.isfinite(fx) and math.isfinite(fy)):
            raise UnreachableError(f"{role} {_fmt(point)} is off the map")
        ix, iy = math.floor(fx), math.floor(fy)
        if not (0 <= ix < width and 0 <= iy < height):
            raise UnreachableError(f"{role} {_fmt(point)} is off the map")
        return iy, ix

    def _goal_cell(self, goal: tuple[float, float]) -> tuple[int, int]:
        cell = self._cell(goal, "goal")
        cost = int(self.costmap.costs[cell])
        if cost == LETHAL:
            raise UnreachableError(f"goal {_fmt(goal)} is inside an obstacle")
        if cost == NO_INFORMATION:
            raise UnreachableError(f"goal {_fmt(goal)} is in unknown space")
        if cost == INSCRIBED:
            raise UnreachableError(f"goal {_fmt(goal)} is too close to an obstacle for the robot")
        return cell

    def _start_cell(self, start: tuple[float, float]) -> tuple[int, int]:
        iy, ix = self._cell(start, "start")
        if self.costmap.costs[iy, ix] < INSCRIBED:
            return iy, ix
        traversable = self.costmap.costs < INSCRIBED
        if self._nearest_free is None:
            from scipy.ndimage import distance_transform_edt

            _, nearest = distance_transform_edt(~traversable, return_indices=True)
            self._nearest_free = np.asarray(nearest)
        ny, nx = (int(v) for v in self._nearest_free[:, iy, ix])
        snap = math.hypot(ny - iy, nx - ix) * self.costmap.grid.resolution
        if snap > self.params.start_snap_m or not traversable[ny, nx]:
            raise StartInObstacleError(f"start {_fmt(start)} is inside an obstacle")
        return ny, nx

    def _make_path(
        self,
        cells: npt.NDArray[np.intp],
        cost: float,
        start: tuple[float, float],
        goal: tuple[float, float],
    ) -> Path:
        xs, ys = self.costmap.grid.cell_to_world(cells[:, 1], cells[:, 0])
        points = np.empty((len(cells), 2), dtype=np.float64)
        points[:, 0], points[:, 1] = xs, ys
        # Exact endpoints: the robot starts where it is and stops on the anchor.
        points[0], points[-1] = start, goal
        if self.params.smooth and len(points) > 2:
            points = shortcut(points, self.costmap)
        return Path(points, _length(points), cost, len(cells))

    def _compiled_path(
        self, planned: grid_astar.Found, start: tuple[float, float], goal: tuple[float, float]
    ) -> Path:
        """The path of a compiled plan: its waypoints were smoothed in C already (the same
        shortcuts); only their world points are left to find. A smoothed path has a handful
        of them: plain floats then, as numpy's per-call cost was a fifth of a small plan."""
        grid = self.costmap.grid
        if len(planned.flat) > _FEW_WAYPOINTS:
            rows, cols = np.divmod(planned.flat, self.costmap.costs.shape[1])
            xs, ys = grid.cell_to_world(cols, rows)
            points = np.empty((len(xs), 2), dtype=np.float64)
            points[:, 0], points[:, 1] = xs, ys
            points[0], points[-1] = start, goal  # the robot's exact start, the anchor itself
            return Path(points, _length(points), planned.cost, planned.path_cells)
        width, res = self.costmap.costs.shape[1], grid.resolution
        yaw, ox, oy = grid.origin_yaw, grid.origin_x, grid.origin_y
        c, s = math.cos(yaw), math.sin(yaw)
        waypoints = [start]
        for cell in planned.flat.tolist()[1:-1]:  # cell_to_world, one cell at a time
            row, col = divmod(cell, width)
            gx, gy = (col + 0.5) * res, (row + 0.5) * res
            if yaw == 0.0:
                waypoints.append((ox + gx, oy + gy))
            else:
                waypoints.append((ox + c * gx - s * gy, oy + s * gx + c * gy))
        waypoints.append(goal)
        length = 0.0
        for (x0, y0), (x1, y1) in itertools.pairwise(waypoints):
            length += math.sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0))
        points = np.array(waypoints, dtype=np.float64)
        return Path(points, length, planned.cost, planned.path_cells)


_NO_MARKS = (0, 0)


@dataclass(frozen=True)
class _Box:
    """The costs a compiled search runs on: a box of the map holding every traversable cell
    (its costs, its first row and column and the map's height and width) and the landmark
    table measured over the same box."""

    costs: npt.NDArray[np.uint8]
    corner: tuple[int, int, int, int]
    marks: tuple[int, int]


_FEW_WAYPOINTS = 32  # up to this many, a compiled plan's world points are found in plain floats


def _length(points: npt.NDArray[np.float64]) -> float:
    """A polyline's length (m): the norm's own sum, without linalg's checks."""
    steps = np.diff(points, axis=0)
    return float(np.sqrt((steps * steps).sum(axis=1)).sum())


def costmap_graph(
    costmap: Costmap, cost_penalty: float
) -> tuple[csr_matrix, npt.NDArray[np.int32]]:
    """The graph every search here runs on, over the whole map: (CSR matrix, node id of each
    cell, -1 where not traversable). For comparing against a full Dijkstra (bench, tests)."""
    traversable = costmap.traversable
    ids = np.full(traversable.shape, -1, dtype=np.int32)
    ids[traversable] = np.arange(int(traversable.sum()), dtype=np.int32)
    res = costmap.grid.resolution
    return _graph(ids, traversable, traversable, costmap.costs, res, cost_penalty), ids


def _graph(
    ids: npt.NDArray[np.int32],
    nodes: npt.NDArray[np.bool_],
    traversable: npt.NDArray[np.bool_],
    block: npt.NDArray[np.uint8],
    res: float,
    cost_penalty: float,
) -> csr_matrix:
    """The 8-connected graph of ``nodes`` in CSR form, built row by row without a COO copy
    (int32 indices, 12 bytes an edge): each node's edges in a fixed direction order."""
    height, width = nodes.shape
    count = int(ids.max()) + 1 if ids.size else 0
    directions = [(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx]
    valid: list[npt.NDArray[np.bool_]] = []
    for dy, dx in directions:
        ok = np.zeros((height, width), dtype=bool)
        ys, ys2 = slice(max(0, -dy), height - max(0, dy)), slice(max(0, dy), height + min(0, dy))
        xs, xs2 = slice(max(0, -dx), width - max(0, dx)), slice(max(0, dx), width + min(0, dx))
        edge = nodes[ys, xs] & nodes[ys2, xs2]
        if dy and dx:  # no corner cutting: both side cells must be traversable
            edge &= traversable[ys2, xs] & traversable[ys, xs2]
        ok[ys, xs] = edge
        valid.append(ok[nodes])
    degree = np.zeros(count, dtype=np.int32)
    for ok_nodes in valid:
        degree += ok_nodes
    indptr = np.zeros(count + 1, dtype=np.int64 if degree.sum() >= 2**31 else np.int32)
    np.cumsum(degree, out=indptr[1:])
    nnz = int(indptr[-1])
    indices = np.empty(nnz, dtype=np.int32)
    data = np.empty(nnz, dtype=np.float64)
    offset = indptr[:-1].copy()
    node_y, node_x = (v.astype(np.int32) for v in np.nonzero(nodes))
    node_cost = block[node_y, node_x].astype(np.float64)
    for (dy, dx), ok_nodes in zip(directions, valid, strict=True):
        at = offset[ok_nodes]
        ny, nx = node_y[ok_nodes] + dy, node_x[ok_nodes] + dx
        indices[at] = ids[ny, nx]
        mean_cost = (node_cost[ok_nodes] + block[ny, nx]) / 2
        length = res * math.hypot(dy, dx)
        data[at] = length * (1 + cost_penalty * mean_cost / (INSCRIBED - 1))
        offset[ok_nodes] = at + 1
    from scipy.sparse import csr_matrix

    return csr_matrix((data, indices, indptr), shape=(count, count))


def _octile(dy: Any, dx: Any) -> Any:
    """The 8-connected grid distance (cells): no path between two cells is shorter."""
    ay, ax = np.abs(dy), np.abs(dx)
    return np.maximum(ay, ax) + (math.sqrt(2.0) - 1.0) * np.minimum(ay, ax)


def _walk_back(pred: npt.NDArray[np.int32], goal: int) -> list[int]:
    nodes = [goal]
    node = int(pred[goal])
    while node >= 0:
        nodes.append(node)
        node = int(pred[node])
    nodes.reverse()
    return nodes


def _segment_max_cost(
    costs: npt.NDArray[np.uint8], a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]
) -> int:
    """The highest cost on the segment a-b (grid-frame points in cells), sampled every half
    cell. Called some ten times a waypoint: plain array arithmetic, no clip or linspace
    (their per-call overhead was most of a plan's smoothing)."""
    n = max(2, math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) * 2.0) + 1)
    t = np.arange(n) / (n - 1)
    height, width = costs.shape
    ix = np.minimum(np.maximum(np.floor(a[0] + t * (b[0] - a[0])), 0), width - 1).astype(np.intp)
    iy = np.minimum(np.maximum(np.floor(a[1] + t * (b[1] - a[1])), 0), height - 1).astype(np.intp)
    return int(costs[iy, ix].max())


def shortcut(points: npt.NDArray[np.float64], costmap: Costmap) -> npt.NDArray[np.float64]:
    """Greedy line-of-sight shortcuts that stay as far from obstacles as the grid path did."""
    grid = costmap.grid
    gx, gy = grid.to_grid_frame(points[:, 0], points[:, 1])
    in_cells = np.column_stack([gx, gy]) / grid.resolution  # the grid's frame, cell units
    ix = np.clip(np.floor(in_cells[:, 0]), 0, grid.width - 1).astype(np.intp)
    iy = np.clip(np.floor(in_cells[:, 1]), 0, grid.height - 1).astype(np.intp)
    along = costmap.costs[iy, ix].astype(np.int64)
    out = [points[0]]
    i, n = 0, len(points)
    while i < n - 1:
        lo, hi = i + 1, n - 1
        best = lo
        # Binary search for the farthest visible waypoint; visibility is near-monotone here.
        while lo <= hi:
            mid = (lo + hi) // 2
            # A little slack (10 of 252) lets corners round off without hugging walls.
            allowed = min(int(along[i : mid + 1].max()) + 10, INSCRIBED - 1)
            if _segment_max_cost(costmap.costs, in_cells[i], in_cells[mid]) <= allowed:
                best, lo = mid, mid + 1
            else:
                hi = mid - 1
        out.append(points[best])
        i = best
    return np.asarray(out)


def resample_polyline(points: npt.NDArray[np.float64], spacing_m: float) -> npt.NDArray[np.float64]:
    """Points every ``spacing_m`` along a polyline, keeping both ends."""
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.r_[0.0, np.cumsum(seg)]
    if s[-1] == 0.0:
        return points[:1].copy()
    samples = np.r_[np.arange(0.0, s[-1], spacing_m), s[-1]]
    return np.column_stack(
        [np.interp(samples, s, points[:, 0]), np.interp(samples, s, points[:, 1])]
    )


def _fmt(point: tuple[float, float]) -> str:
    return f"({point[0]:.2f}, {point[1]:.2f})"
