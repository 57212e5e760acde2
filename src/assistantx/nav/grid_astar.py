"""A* on a costmap's grid, in C (``_grid_astar.c``), called through ctypes.

The same graph and edge weights as the planner's Dijkstra, searched towards the goal with
the octile distance, or the landmark bound where it is larger (``landmarks``), as heuristic:
an exact search that stops at the goal and touches the cells on the goal's side first, where
a full Dijkstra settles the whole floor. ``distances`` is that full Dijkstra, for measuring
the landmarks. The extension
is built with the package (``pyproject.toml``, optional: where no C compiler was at hand it
is missing, ``available()`` says so and the planner searches with scipy instead).

``plan`` is the planner's whole query in one call: the search, the path's cells and the
planner's line-of-sight smoothing (``planner.shortcut``'s steps, bit for bit). On a small
floor those steps in Python, and numpy's per-call cost on a few waypoints, were most of a
plan (tb3_sandbox: a plan 1.7x a full Dijkstra, the search alone 0.3x).
"""

from __future__ import annotations

import ctypes
import logging
import math
import threading
from collections.abc import Callable
from functools import cache
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import numpy.typing as npt

from assistantx.nav.costmap import INSCRIBED

if TYPE_CHECKING:
    from assistantx.nav.occupancy_map import OccupancyMap

logger = logging.getLogger(__name__)

# Buffers go to C as plain addresses: numpy's ndpointer checks cost more per call than a
# search on a small floor (five arrays, a few microseconds each).
_ADDRESS = ctypes.c_void_p
_Frame = ctypes.c_double * 6  # the map's frame, as _grid_astar.c's `frame`
_STATE_BYTES = 16  # sizeof(cell_state)
_LAST_GENERATION = 2**29 - 1  # a cell's tag keeps the generation above 3 bits


@cache
def _library() -> ctypes.CDLL | None:
    """The extension as a C library, for ``grid_distances`` (the plans call its Python
    function ``plan``); None where it was not built or is out of date."""
    try:
        from assistantx.nav import _grid_astar  # type: ignore[attr-defined]
    except ImportError:
        logger.info("the compiled A* is not built; plans search with scipy's Dijkstra")
        return None
    if not hasattr(_grid_astar, "plan"):  # a stale build of an older source
        logger.warning("the compiled A* is out of date (rebuild the package); using scipy")
        return None
    library = ctypes.CDLL(_grid_astar.__file__)
    int32, double = ctypes.c_int32, ctypes.c_double
    distances = library.grid_distances
    distances.restype = int32
    distances.argtypes = [_ADDRESS, int32, int32, int32, double, double, int32, _ADDRESS]
    distances.argtypes += [ctypes.c_uint32, _ADDRESS, int32]
    return library


class _Workspace(threading.local):
    """A thread's per-cell search state (``cell_state`` in C, 16 bytes a cell), kept between
    searches on grids of one size: allocating it afresh cost more than the search itself on
    a small floor (fresh pages fault in). Its address is kept with it (asking numpy for one
    costs about a microsecond)."""

    size = -1
    generation = 0  # the search's number: a cell's state counts where its stamp equals it
    states: npt.NDArray[np.uint8]
    address = 0

    def __init__(self) -> None:
        self.path = np.empty(1024, dtype=np.int32)  # the last path's cells (first the kept)
        self.path_address = self.path.ctypes.data

    def next_search(self, size: int) -> int:
        """Ready the state for a search on ``size`` cells; the search's generation."""
        if size != self.size or self.generation == _LAST_GENERATION:
            self.states = np.zeros(size * _STATE_BYTES, dtype=np.uint8)  # every tag 0
            self.address = self.states.ctypes.data
            self.size, self.generation = size, 0
        self.generation += 1
        return self.generation

    def grow_path(self, length: int) -> None:
        """Room for a path of ``length`` cells (grown by doubling, kept)."""
        if len(self.path) < length:
            self.path = np.empty(max(length, 2 * len(self.path)), dtype=np.int32)
            self.path_address = self.path.ctypes.data


_workspace = _Workspace()


def available() -> bool:
    """Whether the compiled search was built with this installation."""
    return _library() is not None


class Found(NamedTuple):
    """A compiled plan: its waypoints' flat cells (row * width + col; the kept ones when
    smoothed, else every cell of the path), the path's cost and its number of grid cells."""

    flat: npt.NDArray[np.intp]
    cost: float
    path_cells: int


class MapFrame:
    """A map's frame as the compiled smoothing takes it (``frame`` in C): made once per map,
    as packing it costs about as much per plan as a tenth of a small search."""

    def __init__(self, grid: OccupancyMap) -> None:
        yaw = grid.origin_yaw
        rotated = 0.0 if yaw == 0.0 else 1.0
        self.packed = _Frame(
            grid.origin_x, grid.origin_y, math.cos(yaw), math.sin(yaw), rotated, grid.resolution
        )
        self.address = ctypes.addressof(self.packed)


def traversable_box(costs: npt.NDArray[np.uint8]) -> tuple[int, int, int, int]:
    """The box round the traversable cells (y0, y1, x0, x1), all a compiled search can
    reach: on a map whose free space is a small part of its grid, searching the box's costs
    alone keeps the search's state and the landmarks' table small and close together."""
    traversable = costs < INSCRIBED
    rows, cols = np.flatnonzero(traversable.any(axis=1)), np.flatnonzero(traversable.any(axis=0))
    if not len(rows):
        return (0, 0, 0, 0)
    return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1


def distances(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    source: int,
    out: npt.NDArray[np.float32],
    column: int,
) -> int:
    """The cheapest cost from flat cell ``source`` to every cell (a full Dijkstra on the
    search's graph) into column ``column`` of ``out`` ((cells, columns), C order, float32;
    -1 where unreached); the number of cells reached. Requires ``available()``."""
    library = _library()
    if library is None:
        raise RuntimeError("the compiled A* is not built")
    grid = np.ascontiguousarray(costs, dtype=np.uint8)
    height, width = grid.shape
    if out.shape[0] != height * width or not out.flags.c_contiguous or out.dtype != np.float32:
        raise ValueError("out must be a C-ordered float32 array with a row per cell")
    if height * width >= 2**31:
        raise ValueError("a grid of 2**31 cells or more is beyond the compiled search")
    work = _workspace
    generation = work.next_search(height * width)
    reached: int = library.grid_distances(
        grid.ctypes.data,
        height,
        width,
        INSCRIBED,
        resolution,
        cost_penalty,
        source,
        work.address,
        generation,
        out.ctypes.data + column * out.itemsize,
        out.shape[1],
    )
    if reached == -2:
        raise MemoryError("the Dijkstra search ran out of memory")
    return reached


def search(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    start: tuple[int, int],
    goal: tuple[int, int],
    marks: tuple[int, int] = (0, 0),
    box: tuple[int, int, int, int] | None = None,
) -> tuple[npt.NDArray[np.intp], float] | None:
    """The cheapest path's (row, col) cells of the map from ``start`` to ``goal`` and its
    cost, or None when no path joins them (``marks`` and ``box`` as for ``plan``). Requires
    ``available()``."""
    found = plan(costs, resolution, cost_penalty, start, goal, None, marks, box)
    if found is None:
        return None
    width = costs.shape[1] if box is None else box[3]
    return np.column_stack(np.divmod(found.flat, width)), found.cost


def plan(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    start: tuple[int, int],
    goal: tuple[int, int],
    smoothing: tuple[MapFrame, tuple[float, float, float, float]] | None,
    marks: tuple[int, int] = (0, 0),
    box: tuple[int, int, int, int] | None = None,
) -> Found | None:
    """The cheapest path from cell ``start`` to cell ``goal`` (row, col), smoothed as
    ``planner.shortcut`` does when ``smoothing`` is given (the map's frame, and the start's
    and the goal's exact world x, y); None when no path joins them. ``marks``: the address
    and column count of a landmark table (``landmarks.Landmarks.marks``; it must bound these
    costs) to steer the search by, (0, 0) for none. ``box``: when ``costs`` are a box of the
    map (every traversable cell inside it), its first row and column and the map's height
    and width; ``start`` and ``goal`` are then the box's cells, the path's are the map's.
    Requires ``available()``."""
    if _library() is None:
        raise RuntimeError("the compiled A* is not built")
    grid = np.ascontiguousarray(costs, dtype=np.uint8)
    height, width = grid.shape
    if box is None:
        box = (0, 0, height, width)
    if box[2] * box[3] >= 2**31:
        raise ValueError("a grid of 2**31 cells or more is beyond the compiled search")
    frame, (sx, sy, gx, gy) = 0, _NO_ENDS
    if smoothing is not None:
        frame, (sx, sy, gx, gy) = smoothing[0].address, smoothing[1]
    source, target = start[0] * width + start[1], goal[0] * width + goal[1]
    work, call = _workspace, _module_plan()
    while True:
        generation = work.next_search(height * width)
        cost, cells, kept = call(
            grid.ctypes.data,
            height,
            width,
            INSCRIBED,
            float(resolution),
            float(cost_penalty),
            source,
            target,
            work.address,
            generation,
            frame,
            float(sx),
            float(sy),
            float(gx),
            float(gy),
            work.path_address,
            len(work.path),
            marks[0],
            marks[1],
            *box,
        )
        if cost == -2.0:
            raise MemoryError("the A* search ran out of memory")
        if cost < 0.0:
            return None
        if kept >= 0:
            break
        work.grow_path(cells)  # a path longer than any before: search again with room
    return Found(work.path[:kept].astype(np.intp), cost, cells)


_NO_ENDS = (0.0, 0.0, 0.0, 0.0)


@cache
def _module_plan() -> Callable[..., tuple[float, int, int]]:
    """``_grid_astar.plan``: grid_plan called without ctypes (see _grid_astar.c)."""
    from assistantx.nav import _grid_astar  # type: ignore[attr-defined]

    function: Callable[..., tuple[float, int, int]] = _grid_astar.plan
    return function
