"""A static costmap: the occupancy map inflated the way nav2's InflationLayer does it.

Costs (uint8, nav2 values): 254 LETHAL on occupied cells, 253 INSCRIBED within
``robot_radius`` of one (the robot's centre there means a collision), then an exponential
decay ``252 * exp(-cost_scaling_factor * (d - robot_radius))`` out to ``inflation_radius``,
0 beyond, and 255 NO_INFORMATION on unknown cells. ``d`` is the Euclidean distance in metres
between cell centres, from an exact distance transform (nav.map_transforms), taken tile by
tile and exact up to ``EXACT_DISTANCE_M`` (``obstacle_distance_m`` is ``inf`` farther out;
every reader compares it with less).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from assistantx.nav import disk_cache, map_transforms
from assistantx.nav.occupancy_map import UNKNOWN, OccupancyMap

FREE_SPACE = 0
INSCRIBED = 253
LETHAL = 254
NO_INFORMATION = 255


@dataclass(frozen=True)
class InflationParams:
    """nav2 inflation_layer parameter names; robot_radius in metres."""

    inflation_radius: float = 0.55
    cost_scaling_factor: float = 10.0
    robot_radius: float = 0.25

    def __post_init__(self) -> None:
        if self.robot_radius < 0 or self.inflation_radius < self.robot_radius:
            raise ValueError("need 0 <= robot_radius <= inflation_radius")
        if self.cost_scaling_factor <= 0:
            raise ValueError("cost_scaling_factor must be positive")


def inflation_cost(distance_m: npt.ArrayLike, params: InflationParams) -> npt.NDArray[np.uint8]:
    """nav2's cost for a cell at ``distance_m`` from the nearest obstacle."""
    d = np.asarray(distance_m, dtype=float)
    cost = np.zeros(d.shape, dtype=np.uint8)
    # Only cells within the inflation radius get a cost: on a big building that is a small
    # part of the map, so the exponential runs over it alone.
    near = d <= params.inflation_radius
    dn = d[near]
    decay = (INSCRIBED - 1) * np.exp(-params.cost_scaling_factor * (dn - params.robot_radius))
    values = np.floor(decay)
    values[dn <= params.robot_radius] = INSCRIBED
    values[dn <= 0.0] = LETHAL
    cost[near] = values.astype(np.uint8)
    return cost


def _map_costs(
    distance_m: npt.NDArray[np.float64], unknown: npt.NDArray[np.bool_], params: InflationParams
) -> npt.NDArray[np.uint8]:
    costs = inflation_cost(distance_m, params)
    costs[unknown] = NO_INFORMATION
    return costs


EXACT_DISTANCE_M = 2.0  # obstacle distances are exact up to here (and the inflation radius)
_TILE = 512  # cells a side


def capped_distance(
    lethal: npt.NDArray[np.bool_], resolution: float, reach_m: float
) -> npt.NDArray[np.float64]:
    """Euclidean distance (m) from each cell centre to the nearest lethal one, exact up to
    ``reach_m`` and ``inf`` beyond. Computed tile by tile, each with a halo of the reach:
    scipy's transform (where the compiled one is not built) of a whole big map holds ~40
    bytes a cell at once (400 MB for a 175 x 142 m floor at 5 cm); a tile's is small, and a
    tile with no obstacle near costs nothing. A nearest obstacle within the reach lies inside
    the halo, so those distances equal the whole map's; a larger one in the tile only says
    the true one is larger too."""
    height, width = lethal.shape
    halo = math.ceil(reach_m / resolution)
    out = np.full(lethal.shape, math.inf)
    for y0 in range(0, height, _TILE):
        for x0 in range(0, width, _TILE):
            y1, x1 = min(height, y0 + _TILE), min(width, x0 + _TILE)
            ya, yb = max(0, y0 - halo), min(height, y1 + halo)
            xa, xb = max(0, x0 - halo), min(width, x1 + halo)
            tile = lethal[ya:yb, xa:xb]
            if not tile.any():
                continue
            cells = map_transforms.distance_to(tile)
            cells = cells[y0 - ya : y1 - ya, x0 - xa : x1 - xa]
            cells[cells > halo] = math.inf
            out[y0:y1, x0:x1] = cells * resolution
    return out


@dataclass(frozen=True, eq=False)
class Costmap:
    grid: OccupancyMap
    costs: npt.NDArray[np.uint8]
    obstacle_distance_m: npt.NDArray[np.float64]
    params: InflationParams

    @classmethod
    def inflate(cls, grid: OccupancyMap, params: InflationParams | None = None) -> Costmap:
        params = params or InflationParams()
        lethal = grid.data >= 65
        # Distance (m) from each cell centre to the nearest lethal cell centre: mapped from
        # the map cache (read-only; what reads it reads a few cells at a time).
        reach_m = max(EXACT_DISTANCE_M, params.inflation_radius)
        distance = disk_cache.cached_array(
            "obstacle-distance",
            (lethal.shape, lethal.tobytes(), grid.resolution, reach_m),
            lambda: capped_distance(lethal, grid.resolution, reach_m),
            mapped=True,
        )
        # The costs follow from those distances, the parameters and the unknown cells: kept
        # too (inflating nav2's warehouse was ~0.02 CPU-s of every start), and read whole,
        # writable: the obstacle layer and the tests write into a costmap's costs.
        inputs = (grid.data.shape, grid.data.tobytes(), grid.resolution, reach_m)
        shape = (params.inflation_radius, params.cost_scaling_factor, params.robot_radius)
        costs = disk_cache.cached_array(
            "inflation-costs",
            (*inputs, *shape),
            lambda: _map_costs(distance, grid.data == UNKNOWN, params),
        )
        return cls(grid, costs, distance, params)

    @property
    def traversable(self) -> npt.NDArray[np.bool_]:
        """Cells the robot's centre may occupy."""
        return self.costs < INSCRIBED

    def cost_at(self, x: float, y: float) -> int:
        """Cost at a world point; NO_INFORMATION off the map."""
        ix, iy = self.grid.world_to_cell(x, y)
        if not (0 <= ix < self.grid.width and 0 <= iy < self.grid.height):
            return NO_INFORMATION
        return int(self.costs[iy, ix])

    def with_obstacles(self, points_xy: npt.NDArray[np.float64]) -> Costmap:
        """A new costmap with the given world points marked occupied (e.g. seen by the LiDAR)."""
        data = self.grid.data.copy()
        ix, iy = self.grid.world_to_cell(points_xy[:, 0], points_xy[:, 1])
        inside = (ix >= 0) & (ix < self.grid.width) & (iy >= 0) & (iy < self.grid.height)
        data[iy[inside], ix[inside]] = 100
        return Costmap.inflate(self.grid.with_data(data), self.params)


Window = tuple[int, int, int, int]  # iy0, iy1, ix0, ix1 (half-open)


def update_obstacles(
    static: Costmap, layered: Costmap, marked: npt.NDArray[np.int64], changed: npt.NDArray[np.int64]
) -> Window | None:
    """Re-inflate, in place in ``layered.costs``, only the bounds around ``changed`` cells.

    ``layered`` starts as a copy of ``static``; ``marked`` are the flat indices of every
    cell the obstacle layer holds now. The window is the box round the changed cells grown
    by the inflation radius (every cell whose cost may change); its costs are recomputed
    from the lethal cells in a box grown by the radius once more, so the result equals a
    full re-inflation of map + marks (nav2's updateBounds, then updateCosts on the bounds).
    Returns the window, or None when nothing changed.
    """
    if changed.size == 0:
        return None
    grid = static.grid
    reach = math.ceil(static.params.inflation_radius / grid.resolution) + 1
    cy, cx = np.divmod(changed, grid.width)
    y0, y1 = max(0, int(cy.min()) - reach), min(grid.height, int(cy.max()) + reach + 1)
    x0, x1 = max(0, int(cx.min()) - reach), min(grid.width, int(cx.max()) + reach + 1)
    my0, my1 = max(0, y0 - reach), min(grid.height, y1 + reach)
    mx0, mx1 = max(0, x0 - reach), min(grid.width, x1 + reach)
    lethal = static.costs[my0:my1, mx0:mx1] == LETHAL
    my, mx = np.divmod(marked, grid.width)
    near = (my >= my0) & (my < my1) & (mx >= mx0) & (mx < mx1)
    lethal[my[near] - my0, mx[near] - mx0] = True
    distance = map_transforms.distance_to(lethal) * grid.resolution  # inf: no lethal cell
    costs = inflation_cost(distance, static.params)
    unknown = (static.costs[my0:my1, mx0:mx1] == NO_INFORMATION) & ~lethal
    costs[unknown] = NO_INFORMATION
    layered.costs[y0:y1, x0:x1] = costs[y0 - my0 : y1 - my0, x0 - mx0 : x1 - mx0]
    return (y0, y1, x0, x1)
