"""A simulated 2D LiDAR: vectorized ray casting on an occupancy grid.

Every beam is marched in steps of half a cell; the first sample that lands in an occupied
cell (``OccupancyMap.obstacles``) ends the beam, and the range is taken half a step before
it, so a range is within a quarter of a cell of the true distance. A beam that hits nothing
within ``max_range_m`` returns ``max_range_m``, as a real scanner reports "no return".

Unknown cells and the space beyond the map edge hold nothing the scanner can see: a beam
passes through them and, if it meets no occupied cell, is a max-range reading. This is the
same world AMCL's likelihood field and the obstacle layer assume (both skip max-range
readings and measure distances to occupied cells only); treating unknown space as a wall
here made the sensor report walls the filter's map does not have. Range noise is Gaussian
with ``range_noise_std_m`` and drawn from the Generator passed in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from assistantx.nav.geometry import FloatArray
from assistantx.nav.occupancy_map import OccupancyMap


@dataclass(frozen=True)
class LidarParams:
    beams: int = 180
    fov_rad: float = 2 * math.pi
    max_range_m: float = 12.0
    min_range_m: float = 0.05
    range_noise_std_m: float = 0.01


@dataclass(frozen=True)
class LaserScan:
    angles: FloatArray  # radians in the robot frame
    ranges: FloatArray  # metres; range_max means no return
    range_min: float
    range_max: float


def beam_angles(params: LidarParams) -> FloatArray:
    full_circle = math.isclose(params.fov_rad, 2 * math.pi)
    return np.linspace(
        -params.fov_rad / 2, params.fov_rad / 2, params.beams, endpoint=not full_circle
    )


def cast_rays(
    blocked: npt.NDArray[np.bool_],
    grid: OccupancyMap,
    pose: FloatArray,
    angles: FloatArray,
    max_range_m: float,
) -> FloatArray:
    """Exact-to-a-quarter-cell distances from ``pose`` along ``angles`` (robot frame)."""
    step = grid.resolution / 2
    t = np.arange(step, max_range_m + step, step)
    heading = pose[2] + angles
    xs = pose[0] + np.cos(heading)[:, None] * t[None, :]
    ys = pose[1] + np.sin(heading)[:, None] * t[None, :]
    ix, iy = grid.world_to_cell(xs, ys)
    inside = (ix >= 0) & (ix < grid.width) & (iy >= 0) & (iy < grid.height)
    hit = np.zeros(inside.shape, dtype=bool)  # off the map: nothing to hit
    hit[inside] = blocked[iy[inside], ix[inside]]
    first = np.argmax(hit, axis=1)
    any_hit = hit[np.arange(len(angles)), first]
    ranges = np.where(any_hit, t[first] - step / 2, max_range_m)
    return np.minimum(ranges, max_range_m)


class Lidar:
    def __init__(self, grid: OccupancyMap, params: LidarParams | None = None) -> None:
        self.grid = grid
        self.params = params or LidarParams()
        self.angles = beam_angles(self.params)
        self._blocked = grid.obstacles

    def set_world(self, grid: OccupancyMap) -> None:
        """Change what the scanner sees (e.g. an obstacle dropped into the world)."""
        self.grid = grid
        self._blocked = grid.obstacles

    def see(self, blocked: npt.NDArray[np.bool_]) -> None:
        """Read what stops a beam from ``blocked`` (same shape as the grid), kept by
        reference: a simulated world that moves people updates it in place."""
        if blocked.shape != self._blocked.shape:
            raise ValueError(f"world shape {blocked.shape} differs from the map's")
        self._blocked = blocked

    @property
    def blocked(self) -> npt.NDArray[np.bool_]:
        return self._blocked

    def scan(self, pose: FloatArray, rng: np.random.Generator) -> LaserScan:
        p = self.params
        true_ranges = cast_rays(self._blocked, self.grid, pose, self.angles, p.max_range_m)
        noisy = true_ranges + rng.normal(0.0, p.range_noise_std_m, true_ranges.shape)
        ranges = np.where(true_ranges >= p.max_range_m, p.max_range_m, noisy)
        ranges = np.clip(ranges, p.min_range_m, p.max_range_m)
        return LaserScan(self.angles, ranges, p.min_range_m, p.max_range_m)
