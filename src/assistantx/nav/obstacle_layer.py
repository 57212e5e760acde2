"""The obstacle layer: what the LiDAR sees that the map does not, marked *and cleared*.

Modelled on nav2's ObstacleLayer: every scan first clears, by ray tracing, the cells each
beam passed through (up to ``raytrace_max_range`` and one cell short of where it ended; a
max-range reading clears its whole traced length), then marks the cell where a beam ended
if the reading is shorter than ``obstacle_max_range``. Two departures, each for a reason:

- only *unmapped* endpoints are marked (farther than ``unmapped_min_m`` from an occupied
  map cell): mapped walls are already in the static layer, and marking them again would
  paint a second, shifted wall whenever the pose estimate is a few centimetres off;
- a mark not seen again for ``decay_s`` expires (nav2's spatio-temporal voxel layer has
  the same idea), so an obstacle that was seen once, e.g. a person walking past, or a false
  return, cannot block a corridor for ever even when no later beam passes through it.

``update`` returns the flat indices of the cells whose mark changed, so the costmap can
re-inflate just the bounds around them (nav2's updateBounds / updateCosts).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from assistantx.nav.geometry import FloatArray
from assistantx.nav.lidar import LaserScan
from assistantx.nav.occupancy_map import OccupancyMap

IntArray = npt.NDArray[np.int64]


@dataclass(frozen=True)
class ObstacleLayerParams:
    """nav2 obstacle_layer names where one exists; ranges in metres, times in seconds."""

    obstacle_max_range: float = 2.5
    raytrace_max_range: float = 3.0
    unmapped_min_m: float = 0.15  # an endpoint this near a mapped wall is that wall
    decay_s: float = 30.0  # not nav2: a mark not re-observed for this long expires


class ObstacleLayer:
    def __init__(
        self,
        grid: OccupancyMap,
        obstacle_distance_m: FloatArray,
        params: ObstacleLayerParams | None = None,
    ) -> None:
        self.grid = grid
        self.params = params or ObstacleLayerParams()
        self._distance = obstacle_distance_m.ravel()  # to the nearest mapped obstacle
        self._seen: dict[int, float] = {}  # flat cell index -> last time it was marked

    @property
    def marked(self) -> IntArray:
        """Flat indices of the cells marked now."""
        return np.fromiter(self._seen.keys(), dtype=np.int64, count=len(self._seen))

    def __len__(self) -> int:
        return len(self._seen)

    def clear(self) -> IntArray:
        changed = self.marked
        self._seen.clear()
        return changed

    def expire(self, now_s: float) -> IntArray:
        """Drop marks older than ``decay_s``; return the cells that changed."""
        old = [c for c, t in self._seen.items() if now_s - t > self.params.decay_s]
        for cell in old:
            del self._seen[cell]
        return np.asarray(old, dtype=np.int64)

    def update(self, pose: FloatArray, scan: LaserScan, now_s: float) -> IntArray:
        """Clear along every beam, mark unmapped endpoints, expire old marks (in that order);
        return the flat indices of the cells whose mark changed."""
        p = self.params
        grid = self.grid
        changed: list[int] = []
        if self._seen:
            traced = self._traced_cells(pose, scan)
            marked = self.marked
            cleared = marked[np.isin(marked, traced)]
            for cell in cleared.tolist():
                del self._seen[cell]
            changed.extend(cleared.tolist())
        hit = (scan.ranges < min(scan.range_max, p.obstacle_max_range)) & (
            scan.ranges > scan.range_min
        )
        if hit.any():
            heading = pose[2] + scan.angles[hit]
            ix, iy = grid.world_to_cell(
                pose[0] + scan.ranges[hit] * np.cos(heading),
                pose[1] + scan.ranges[hit] * np.sin(heading),
            )
            inside = (ix >= 0) & (ix < grid.width) & (iy >= 0) & (iy < grid.height)
            flat = np.unique(iy[inside] * grid.width + ix[inside])
            flat = flat[self._distance[flat] > p.unmapped_min_m]
            for cell in flat.tolist():
                if cell not in self._seen:
                    changed.append(cell)
                self._seen[cell] = now_s
        changed.extend(self.expire(now_s).tolist())
        return np.unique(np.asarray(changed, dtype=np.int64))

    def _traced_cells(self, pose: FloatArray, scan: LaserScan) -> IntArray:
        """Flat indices of the cells the beams passed through (not the cells they ended in)."""
        grid = self.grid
        res = grid.resolution
        limit = np.minimum(scan.ranges, self.params.raytrace_max_range)
        # A beam that returned stops clearing a cell short of its endpoint; a max-range one
        # saw nothing along its whole traced length.
        returned = scan.ranges < scan.range_max
        limit = np.where(returned, limit - res, limit)
        step = res / 2
        t = np.arange(0.0, float(limit.max(initial=0.0)) + step, step)
        heading = pose[2] + scan.angles
        xs = pose[0] + np.cos(heading)[:, None] * t[None, :]
        ys = pose[1] + np.sin(heading)[:, None] * t[None, :]
        ix, iy = grid.world_to_cell(xs, ys)
        keep = (t[None, :] <= limit[:, None]) & (ix >= 0) & (ix < grid.width)
        keep &= (iy >= 0) & (iy < grid.height)
        return np.unique(iy[keep] * grid.width + ix[keep])
