"""A grid planner on an inflated costmap: Dijkstra on scipy.sparse.csgraph, then smoothing.

The graph has one node per traversable cell (cost < INSCRIBED) and 8-connected edges
(diagonals only where both side cells are traversable, so paths never cut a corner). An
edge from u to v weighs ``length_m * (1 + cost_penalty * (c_u + c_v) / 2 / 252)``, the cost
term of nav2's Smac planner: the path keeps away from walls where there is room.

Dijkstra runs in compiled code. A room-to-room query bounds the search with ``limit`` (a
multiple of the straight-line distance, doubled until the goal is settled), so it touches
only the neighbourhood; a query across the floor settles most of the graph (~50 ms).

Obstacles seen while driving do not rebuild the graph: ``layered`` makes a planner that
shares the map planner's nodes and edge structure but owns a copy of the edge weights, and
``update_window`` recomputes only the weights of edges in the re-inflated window (an edge
into a cell that the new costs make untraversable gets the weight BLOCKED, which every
search treats as no edge).

The grid path is then shortened by line-of-sight shortcuts that never pass closer to an
obstacle than the grid path did over the same stretch, and resampled for the controller.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.ndimage import distance_transform_edt
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from assistantx.errors import UnreachableError
from assistantx.robot.costmap import INSCRIBED, LETHAL, NO_INFORMATION, Costmap

_NEIGHBOURS = ((0, 1), (1, 0), (1, 1), (1, -1))  # (dy, dx); the graph is undirected
BLOCKED = 1e12  # the weight of an edge that obstacles seen since the map was made cut


@dataclass(frozen=True)
class PlannerParams:
    cost_penalty: float = 2.0
    start_snap_m: float = 0.5  # a start inside the inscribed zone snaps to free space this near
    smooth: bool = True


@dataclass(frozen=True)
class Path:
    """A planned path: waypoints in metres, its length (m) and its cost (weighted metres)."""

    points: npt.NDArray[np.float64]  # (n, 2)
    length_m: float
    cost: float
    grid_cells: int

    def resampled(self, spacing_m: float = 0.1) -> npt.NDArray[np.float64]:
        return resample_polyline(self.points, spacing_m)


class GridPlanner:
    def __init__(self, costmap: Costmap, params: PlannerParams | None = None) -> None:
        self.costmap = costmap
        self.params = params or PlannerParams()
        traversable = costmap.traversable
        self._node = np.full(traversable.shape, -1, dtype=np.int64)
        self._node[traversable] = np.arange(int(traversable.sum()))
        self._cells = np.argwhere(traversable)  # node -> (iy, ix)
        self._graph = self._build_graph(traversable)
        # For snapping a start that strayed into the inscribed zone back to the nearest node:
        # made on first need (an EDT with indices is the costliest part of set-up).
        self._nearest_free: npt.NDArray[np.intp] | None = None

    def layered(self, costmap: Costmap) -> GridPlanner:
        """A planner on ``costmap`` (the map's costs plus obstacles seen, never lower) that
        shares this one's nodes and edges and owns only a copy of the edge weights."""
        other = object.__new__(GridPlanner)
        other.costmap = costmap
        other.params = self.params
        other._node, other._cells, other._nearest_free = self._node, self._cells, self._nearest_free
        other._graph = csr_matrix(
            (self._graph.data.copy(), self._graph.indices, self._graph.indptr),
            shape=self._graph.shape,
        )
        return other

    def update_window(self, window: tuple[int, int, int, int]) -> None:
        """Recompute the weights of the edges that touch cells of ``window`` from the costs."""
        y0, y1, x0, x1 = window
        # Edges into the window start one cell outside it; diagonals check side cells too.
        h, w = self.costmap.grid.height, self.costmap.grid.width
        block = self._node[max(0, y0 - 1) : min(h, y1 + 1), max(0, x0 - 1) : min(w, x1 + 1)]
        rows = block[block >= 0]
        if rows.size == 0:
            return
        graph = self._graph
        starts, ends = graph.indptr[rows], graph.indptr[rows + 1]
        counts = ends - starts
        entries = np.repeat(starts - np.cumsum(counts) + counts, counts) + np.arange(counts.sum())
        u = np.repeat(rows, counts)
        v = graph.indices[entries]
        uy, ux = self._cells[u, 0], self._cells[u, 1]
        vy, vx = self._cells[v, 0], self._cells[v, 1]
        costs = self.costmap.costs
        ok = (costs[uy, ux] < INSCRIBED) & (costs[vy, vx] < INSCRIBED)
        diagonal = (uy != vy) & (ux != vx)
        ok &= ~diagonal | ((costs[uy, vx] < INSCRIBED) & (costs[vy, ux] < INSCRIBED))
        length = self.costmap.grid.resolution * np.where(diagonal, math.sqrt(2.0), 1.0)
        mean_cost = (costs[uy, ux].astype(np.float64) + costs[vy, vx]) / 2
        weight = length * (1 + self.params.cost_penalty * mean_cost / (INSCRIBED - 1))
        graph.data[entries] = np.where(ok, weight, BLOCKED)

    def _build_graph(self, traversable: npt.NDArray[np.bool_]) -> csr_matrix:
        height, width = traversable.shape
        cost = self.costmap.costs.astype(np.float64)
        res = self.costmap.grid.resolution
        rows, cols, weights = [], [], []
        for dy, dx in _NEIGHBOURS:
            ys = slice(0, height - dy)
            ys2 = slice(dy, height)
            xs = slice(max(0, -dx), width - max(0, dx))
            xs2 = slice(max(0, dx), width + min(0, dx))
            ok = traversable[ys, xs] & traversable[ys2, xs2]
            if dy and dx:  # no corner cutting
                ok &= traversable[ys2, xs] & traversable[ys, xs2]
            mean_cost = (cost[ys, xs] + cost[ys2, xs2])[ok] / 2
            length = res * math.hypot(dy, dx)
            rows.append(self._node[ys, xs][ok])
            cols.append(self._node[ys2, xs2][ok])
            weights.append(length * (1 + self.params.cost_penalty * mean_cost / (INSCRIBED - 1)))
        r, c, w = np.concatenate(rows), np.concatenate(cols), np.concatenate(weights)
        n = len(self._cells)
        return csr_matrix((np.r_[w, w], (np.r_[r, c], np.r_[c, r])), shape=(n, n))

    # -- queries ---------------------------------------------------------------------------
    def plan(self, start: tuple[float, float], goal: tuple[float, float]) -> Path:
        """Plan from start to goal (world metres); raise UnreachableError with the reason."""
        goal_node = self._goal_node(goal)
        start_node = self._start_node(start)
        if start_node == goal_node:
            return self._make_path([start_node], 0.0, start, goal)
        # Path costs run ~5% above the straight line in open space; start the bounded search
        # just above that and widen it (x2.5) a few times before searching the whole graph.
        limit = 1.5 * math.dist(start, goal) + 1.0
        for attempt in range(4):
            bounded = attempt < 3
            dist, pred = dijkstra(
                self._graph,
                indices=start_node,
                return_predecessors=True,
                limit=limit if bounded else np.inf,
            )
            if dist[goal_node] < BLOCKED:
                nodes = _walk_back(pred, goal_node)
                return self._make_path(nodes, float(dist[goal_node]), start, goal)
            limit *= 2.5
        raise UnreachableError(f"goal {_fmt(goal)} is cut off from start {_fmt(start)}")

    def plan_many(
        self, start: tuple[float, float], goals: Sequence[tuple[float, float]]
    ) -> list[Path | None]:
        """Paths from one start to many goals with one full Dijkstra (None: unreachable)."""
        start_node = self._start_node(start)
        dist, pred = dijkstra(self._graph, indices=start_node, return_predecessors=True)
        paths: list[Path | None] = []
        for goal in goals:
            try:
                goal_node = self._goal_node(goal)
            except UnreachableError:
                paths.append(None)
                continue
            if not dist[goal_node] < BLOCKED:
                paths.append(None)
                continue
            nodes = _walk_back(pred, goal_node) if goal_node != start_node else [start_node]
            paths.append(self._make_path(nodes, float(dist[goal_node]), start, goal))
        return paths

    # -- helpers ---------------------------------------------------------------------------
    def _cell(self, point: tuple[float, float], role: str) -> tuple[int, int]:
        grid = self.costmap.grid
        ix, iy = grid.world_to_cell(point[0], point[1])
        if not (0 <= ix < grid.width and 0 <= iy < grid.height):
            raise UnreachableError(f"{role} {_fmt(point)} is off the map")
        return int(iy), int(ix)

    def _goal_node(self, goal: tuple[float, float]) -> int:
        iy, ix = self._cell(goal, "goal")
        cost = int(self.costmap.costs[iy, ix])
        if cost == LETHAL:
            raise UnreachableError(f"goal {_fmt(goal)} is inside an obstacle")
        if cost == NO_INFORMATION:
            raise UnreachableError(f"goal {_fmt(goal)} is in unknown space")
        if cost == INSCRIBED:
            raise UnreachableError(f"goal {_fmt(goal)} is too close to an obstacle for the robot")
        return int(self._node[iy, ix])

    def _start_node(self, start: tuple[float, float]) -> int:
        iy, ix = self._cell(start, "start")
        node = int(self._node[iy, ix])
        if node >= 0:
            return node
        if self._nearest_free is None:
            _, nearest = distance_transform_edt(self._node < 0, return_indices=True)
            self._nearest_free = np.asarray(nearest)
        ny, nx = (int(v) for v in self._nearest_free[:, iy, ix])
        snap = math.hypot(ny - iy, nx - ix) * self.costmap.grid.resolution
        if snap > self.params.start_snap_m or self._node[ny, nx] < 0:
            raise UnreachableError(f"start {_fmt(start)} is inside an obstacle")
        return int(self._node[ny, nx])

    def _make_path(
        self, nodes: list[int], cost: float, start: tuple[float, float], goal: tuple[float, float]
    ) -> Path:
        cells = self._cells[np.asarray(nodes)]
        xs, ys = self.costmap.grid.cell_to_world(cells[:, 1], cells[:, 0])
        points = np.column_stack([xs, ys])
        # Exact endpoints: the robot starts where it is and stops on the anchor.
        points[0], points[-1] = start, goal
        if self.params.smooth and len(points) > 2:
            points = shortcut(points, self.costmap)
        length = float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())
        return Path(points, length, cost, len(nodes))


def _walk_back(pred: npt.NDArray[np.int32], goal: int) -> list[int]:
    nodes = [goal]
    node = int(pred[goal])
    while node >= 0:
        nodes.append(node)
        node = int(pred[node])
    nodes.reverse()
    return nodes


def _segment_max_cost(
    costmap: Costmap, a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]
) -> int:
    grid = costmap.grid
    n = max(2, math.ceil(float(np.linalg.norm(b - a)) / (grid.resolution / 2)) + 1)
    t = np.linspace(0.0, 1.0, n)[:, None]
    pts = a + t * (b - a)
    ix, iy = grid.world_to_cell(pts[:, 0], pts[:, 1])
    ix = np.clip(ix, 0, grid.width - 1)
    iy = np.clip(iy, 0, grid.height - 1)
    return int(costmap.costs[iy, ix].max())


def shortcut(points: npt.NDArray[np.float64], costmap: Costmap) -> npt.NDArray[np.float64]:
    """Greedy line-of-sight shortcuts that stay as far from obstacles as the grid path did."""
    grid = costmap.grid
    ix, iy = grid.world_to_cell(points[:, 0], points[:, 1])
    ix = np.clip(ix, 0, grid.width - 1)
    iy = np.clip(iy, 0, grid.height - 1)
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
            if _segment_max_cost(costmap, points[i], points[mid]) <= allowed:
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
