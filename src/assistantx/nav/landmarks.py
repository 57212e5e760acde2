"""Landmark distances: a lower bound on a path's cost that the A* can steer by.

For a few landmark cells L, the cost from L to every cell is measured once per costmap (a
full Dijkstra each). Then for any cell v and goal g, ``|d(L, g) - d(L, v)| <= d(v, g)`` (the
triangle inequality; the graph is undirected), so the largest of these bounds and the octile
distance is still a lower bound on the cost left, and a much closer one where walls and
inflated cells make paths dearer than the straight line: on the turtlebot sandbox the A*
then settles ~1/10 of the cells the octile distance alone lets through (the ALT heuristic of
Goldberg and Harrelson).

The bounds hold for any costs at least those they were measured on (a dearer edge or a cell
no longer traversable only lengthens d(v, g)), so a planner on the map's costs plus obstacles
seen keeps the map's landmarks; where a cost falls below them, the landmarks are dropped
(``bounds``). Landmarks are picked farthest-first in the largest free component: a corner,
then each the cell farthest from those picked so far.
"""

from __future__ import annotations

import threading
import uuid
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from assistantx.nav import disk_cache, grid_astar

DEFAULT_COUNT = 8  # landmarks per map: see the README's planning figures
# The table holds 4 bytes a cell a landmark: on a floor so big that the count asked for
# would pass this, fewer are measured (none where fewer than 2 fit): 8 up to 2 M cells.
TABLE_BUDGET_BYTES = 64 * 2**20
_KIND = "planner-landmarks"
# The last landmarks measured, by the hash of their costs: every robot, runtime and planning
# worker on the same map in one process shares them instead of measuring them again.
_KEEP = 2
_recent: OrderedDict[str, Landmarks] = OrderedDict()
_lock = threading.Lock()


@dataclass(frozen=True, eq=False)
class Landmarks:
    """Each cell's cost from each landmark, and the costs they were measured on."""

    # (cells of the box, landmarks), C order; -1 where unreached
    table: npt.NDArray[np.float32]
    measured_on: npt.NDArray[np.uint8]  # a copy of the map's costs measured
    box: tuple[int, int, int, int]  # y0, y1, x0, x1: the traversable cells' box, the table's
    token: str = field(default_factory=lambda: uuid.uuid4().hex)  # for the planning worker

    @property
    def marks(self) -> tuple[int, int]:
        """The table's address and column count, as ``grid_astar.plan`` takes them."""
        return self.table.ctypes.data, self.table.shape[1]

    def bounds(
        self, costs: npt.NDArray[np.uint8], window: tuple[int, int, int, int] | None = None
    ) -> bool:
        """Whether the bounds hold on ``costs``: no cost (in ``window``, y0, y1, x0, x1, when
        only those changed) below the costs they were measured on."""
        if costs.shape != self.measured_on.shape:
            return False
        if window is None:
            return bool(np.all(costs >= self.measured_on))
        y0, y1, x0, x1 = window
        return bool(np.all(costs[y0:y1, x0:x1] >= self.measured_on[y0:y1, x0:x1]))


def measure_landmarks(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    components: npt.NDArray[np.int32],
    count: int = DEFAULT_COUNT,
    budget_bytes: int = TABLE_BUDGET_BYTES,
) -> Landmarks | None:
    """Up to ``count`` landmarks (as many as fit in ``budget_bytes``) in the largest
    component of ``components`` (the traversable cells' labels, 0 elsewhere), kept in the
    map cache by the costs they are measured on; None when fewer than 2 fit, there is no
    traversable cell or the compiled search is not built."""
    y0, y1, x0, x1 = box = grid_astar.traversable_box(costs)
    count = min(count, budget_bytes // (4 * max(1, (y1 - y0) * (x1 - x0))))
    if count < 2 or not grid_astar.available() or not components.any():
        return None
    measured_on = np.array(costs, dtype=np.uint8, order="C")
    inside = np.ascontiguousarray(measured_on[y0:y1, x0:x1])
    inputs = (measured_on.shape, measured_on.tobytes(), resolution, cost_penalty, count)
    key = disk_cache.content_key(_KIND, inputs)
    with _lock:
        found = _recent.get(key)
        if found is None:
            table = disk_cache.cached_array(
                _KIND,
                inputs,
                lambda: _measure(inside, resolution, cost_penalty, components[y0:y1, x0:x1], count),
            )
            found = Landmarks(table, measured_on, box)
            _recent[key] = found
            while len(_recent) > _KEEP:
                _recent.popitem(last=False)
        else:
            _recent.move_to_end(key)
        return found


def _measure(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    components: npt.NDArray[np.int32],
    count: int,
) -> npt.NDArray[np.float32]:
    sizes = np.bincount(components.ravel())
    sizes[0] = 0
    cells = np.flatnonzero(components.ravel() == int(np.argmax(sizes)))
    # The first landmark is the cell of the largest component farthest from its centroid
    # (a corner, found without a Dijkstra); each next one the cell whose cost from every
    # landmark so far is the highest (unreached cells, -1, are never picked).
    rows, cols = np.divmod(cells, costs.shape[1])
    landmark = int(cells[np.argmax(np.hypot(rows - rows.mean(), cols - cols.mean()))])
    table = np.empty((costs.size, count), dtype=np.float32)
    nearest = np.empty(costs.size, dtype=np.float32)
    for k in range(count):
        grid_astar.distances(costs, resolution, cost_penalty, landmark, table, k)
        if k == 0:
            nearest[:] = table[:, 0]
        else:
            np.minimum(nearest, table[:, k], out=nearest)
        landmark = int(np.argmax(nearest))
    return table
