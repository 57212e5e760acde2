"""A* on a costmap's grid, in C (``_grid_astar.c``), called through ctypes.

The same graph and edge weights as the planner's Dijkstra, searched towards the goal with
the octile distance as heuristic: an exact search that stops at the goal and touches the
cells on the goal's side first, where a full Dijkstra settles the whole floor. The extension
is built with the package (``pyproject.toml``, optional: where no C compiler was at hand it
is missing, ``available()`` says so and the planner searches with scipy instead).
"""

from __future__ import annotations

import ctypes
import logging
import threading
from functools import cache

import numpy as np
import numpy.typing as npt

from assistantx.nav.costmap import INSCRIBED

logger = logging.getLogger(__name__)

_DOUBLE_P = np.ctypeslib.ndpointer(np.float64, flags="C_CONTIGUOUS")
_INT32_P = np.ctypeslib.ndpointer(np.int32, flags="C_CONTIGUOUS")
_UINT8_P = np.ctypeslib.ndpointer(np.uint8, flags="C_CONTIGUOUS")


@cache
def _library() -> ctypes.CDLL | None:
    try:
        from assistantx.nav import _grid_astar  # type: ignore[attr-defined]
    except ImportError:
        logger.info("the compiled A* is not built; plans search with scipy's Dijkstra")
        return None
    library = ctypes.CDLL(_grid_astar.__file__)
    function = library.grid_astar
    function.restype = ctypes.c_double
    function.argtypes = [
        _UINT8_P,
        ctypes.c_int32,
        ctypes.c_int32,
        ctypes.c_int32,
        ctypes.c_double,
        ctypes.c_double,
        ctypes.c_int32,
        ctypes.c_int32,
        _DOUBLE_P,
        _INT32_P,
        _INT32_P,
        np.ctypeslib.ndpointer(np.uint32, flags="C_CONTIGUOUS"),
        ctypes.c_uint32,
    ]
    return library


class _Workspace(threading.local):
    """A thread's per-cell arrays, kept between searches on grids of one size: allocating
    them afresh cost more than the search itself on a small floor (fresh pages fault in)."""

    size = -1
    generation = 0  # the search's number: a cell's entries count where its stamp equals it
    g: npt.NDArray[np.float64]
    parent: npt.NDArray[np.int32]
    where: npt.NDArray[np.int32]
    stamp: npt.NDArray[np.uint32]

    def next_search(self, size: int) -> int:
        """Ready the arrays for a search on ``size`` cells; the search's generation."""
        if size != self.size or self.generation == 2**32 - 1:
            self.g = np.empty(size, dtype=np.float64)
            self.parent = np.empty(size, dtype=np.int32)
            self.where = np.empty(size, dtype=np.int32)
            self.stamp = np.zeros(size, dtype=np.uint32)
            self.size, self.generation = size, 0
        self.generation += 1
        return self.generation


_workspace = _Workspace()


def available() -> bool:
    """Whether the compiled search was built with this installation."""
    return _library() is not None


def search(
    costs: npt.NDArray[np.uint8],
    resolution: float,
    cost_penalty: float,
    start: tuple[int, int],
    goal: tuple[int, int],
) -> tuple[npt.NDArray[np.intp], float] | None:
    """The cheapest path's (row, col) cells from ``start`` to ``goal`` and its cost, or None
    when no path joins them. Requires ``available()``."""
    library = _library()
    if library is None:
        raise RuntimeError("the compiled A* is not built")
    grid = np.ascontiguousarray(costs, dtype=np.uint8)
    height, width = grid.shape
    if height * width >= 2**31:
        raise ValueError("a grid of 2**31 cells or more is beyond the compiled search")
    work = _workspace
    generation = work.next_search(height * width)
    source, target = start[0] * width + start[1], goal[0] * width + goal[1]
    cost = library.grid_astar(
        grid,
        height,
        width,
        INSCRIBED,
        resolution,
        cost_penalty,
        source,
        target,
        work.g,
        work.parent,
        work.where,
        work.stamp,
        generation,
    )
    if cost == -2.0:
        raise MemoryError("the A* search ran out of memory")
    if cost < 0.0:
        return None
    nodes = [target]
    while nodes[-1] != source:
        nodes.append(int(work.parent[nodes[-1]]))
    nodes.reverse()
    flat = np.asarray(nodes, dtype=np.intp)
    return np.column_stack(np.divmod(flat, width)), cost
