"""The simulated world apart from the map: what is really there, which the robot never reads.

The robot knows its map and its sensor; ``GroundTruth`` is what the simulated LiDAR sees and
what a collision is measured against:

- the map's occupied cells, plus every *unknown* cell that borders free space: on a SLAM map
  the grey rim of the known floor is where the mapping laser stopped, i.e. a wall or
  furniture it saw only edge-on, so a simulated beam stops there instead of passing through
  (on Willow Garage 14% of beams went to max range through such rims);
- the scenario's changes (scenario.py): boxes and chairs moved, doors closed, corridors
  blocked, all static rectangles or segments stamped into the grid;
- people walking to and fro along their paths at walking speed. A person who would come
  within ``yield_gap_m`` of the robot's footprint stops, as people do; one held up for
  ``turn_back_s`` turns round, so a head-on meeting in a corridor cannot deadlock.

``blocked`` is one boolean array updated in place as people move (only their cells change),
so the LiDAR can keep a reference to it. ``clearance_m`` is the distance from the robot's
footprint to the nearest solid thing or person: negative or zero is a collision.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from assistantx.nav import disk_cache, map_transforms
from assistantx.nav.geometry import FloatArray
from assistantx.nav.occupancy_map import OccupancyMap

BoolArray = npt.NDArray[np.bool_]


@dataclass(frozen=True)
class Box:
    """An axis-aligned rectangle of furniture, boxes or a barrier; centre and size in metres."""

    x: float
    y: float
    width_m: float
    depth_m: float
    name: str = "an obstacle"


@dataclass(frozen=True)
class Door:
    """A closed door: a solid segment ``thickness_m`` thick from ``start`` to ``end``."""

    start: tuple[float, float]
    end: tuple[float, float]
    name: str = "a door"
    thickness_m: float = 0.1
    opens_after_s: float | None = None  # a scenario event: someone opens it then (office clock)


@dataclass(frozen=True)
class WalkerSpec:
    """A person walking to and fro along ``path`` (metres) at ``speed_mps``."""

    path: tuple[tuple[float, float], ...]
    speed_mps: float = 1.2
    radius_m: float = 0.25

    def __post_init__(self) -> None:
        if len(self.path) < 2:
            raise ValueError("a walking path needs at least two points")
        if not 0 < self.speed_mps <= 3.0 or not 0 < self.radius_m <= 1.0:
            raise ValueError("walking speed must be in (0, 3] m/s and radius in (0, 1] m")


@dataclass
class Walker:
    """One person's state: how far along the to-and-fro path (arc length, metres)."""

    spec: WalkerSpec
    s_m: float
    direction: int = 1
    held_s: float = 0.0
    points: FloatArray = field(init=False)
    arc_m: FloatArray = field(init=False)

    def __post_init__(self) -> None:
        self.points = np.asarray(self.spec.path, dtype=float)
        seg = np.hypot(*np.diff(self.points, axis=0).T)
        self.arc_m = np.r_[0.0, np.cumsum(seg)]

    @property
    def length_m(self) -> float:
        return float(self.arc_m[-1])

    def at(self, s_m: float) -> FloatArray:
        s = min(max(s_m, 0.0), self.length_m)
        return np.array(
            [
                np.interp(s, self.arc_m, self.points[:, 0]),
                np.interp(s, self.arc_m, self.points[:, 1]),
            ]
        )

    @property
    def position(self) -> FloatArray:
        return self.at(self.s_m)

    def next_s(self, dt_s: float) -> tuple[float, int]:
        s = self.s_m + self.direction * self.spec.speed_mps * dt_s
        if s > self.length_m:
            return 2 * self.length_m - s, -1
        if s < 0.0:
            return -s, 1
        return s, self.direction


class GroundTruth:
    def __init__(
        self,
        grid: OccupancyMap,
        *,
        boxes: Sequence[Box] = (),
        doors: Sequence[Door] = (),
        walkers: Sequence[WalkerSpec] = (),
        rng: np.random.Generator | None = None,
        robot_radius_m: float = 0.25,
        yield_gap_m: float = 0.2,
        turn_back_s: float = 3.0,
        trail_every_s: float | None = None,
    ) -> None:
        self.grid = grid
        self.boxes, self.doors = tuple(boxes), tuple(doors)
        self.robot_radius_m = robot_radius_m
        self.yield_gap_m = yield_gap_m
        self.turn_back_s = turn_back_s
        # Where each person was, every ``trail_every_s`` (for a picture of the run).
        self.trail_every_s = trail_every_s
        self.trails: list[list[tuple[float, float]]] = [[] for _ in walkers]
        self.time_s = 0.0
        self._next_trail_s = 0.0
        self.static: BoolArray = self._solid()
        # Metres from each cell centre to the nearest solid cell's edge (half a cell less
        # than centre to centre), for the collision check.
        self._static_distance_m = self._distance_m(self.static)
        rng = rng or np.random.default_rng(0)
        self.walkers = [Walker(spec, float(rng.uniform(0.0, 1.0))) for spec in walkers]
        for walker in self.walkers:
            walker.s_m *= walker.length_m
            walker.direction = 1 if rng.random() < 0.5 else -1
        self.blocked: BoolArray = self.static.copy()
        self._stamped = np.zeros(0, dtype=np.int64)
        self._stamp_people()

    def _solid(self) -> BoolArray:
        """Walls, the grey rim, the boxes and the doors that are shut."""
        grid = self.grid
        static = grid.obstacles | grid.unknown_rim
        cx, cy = grid.cell_to_world(*np.meshgrid(np.arange(grid.width), np.arange(grid.height)))
        for box in self.boxes:
            static |= (np.abs(cx - box.x) <= box.width_m / 2) & (
                np.abs(cy - box.y) <= box.depth_m / 2
            )
        for door in self.doors:
            static |= _segment_distance(cx, cy, door.start, door.end) <= door.thickness_m / 2
        return static

    def _distance_m(self, static: BoolArray) -> FloatArray:
        # cached by the solid cells' content: a second start on the same floor reads it
        centre = disk_cache.cached_array(
            "solid-distance",
            (static.shape, np.packbits(static).tobytes()),
            lambda: _distance_to_solid(static),
        )
        return np.maximum(centre - 0.5, 0.0) * self.grid.resolution

    # -- doors -----------------------------------------------------------------------------
    def open_door(self, name: str) -> None:
        """Someone opens the door called ``name``: it is solid no more. The arrays the
        sensors read are changed in place (they hold them by reference)."""
        doors = tuple(d for d in self.doors if d.name != name)
        if len(doors) == len(self.doors):
            raise KeyError(f"no closed door called {name!r}")
        self.doors = doors
        self.static[...] = self._solid()
        self._static_distance_m = self._distance_m(self.static)
        self.blocked[...] = self.static
        self._stamped = np.zeros(0, dtype=np.int64)
        self._stamp_people()

    # -- people ----------------------------------------------------------------------------
    @property
    def people(self) -> FloatArray:
        """(n, 2) positions of the people now."""
        if not self.walkers:
            return np.zeros((0, 2))
        return np.array([w.position for w in self.walkers])

    def advance(self, dt_s: float, robot_xy: FloatArray | None = None) -> None:
        """Move every person ``dt_s`` seconds along their path, yielding to the robot."""
        self.time_s += dt_s
        if not self.walkers:
            return
        if self.trail_every_s is not None and self.time_s >= self._next_trail_s:
            self._next_trail_s = self.time_s + self.trail_every_s
            for trail, walker in zip(self.trails, self.walkers, strict=True):
                trail.append((float(walker.position[0]), float(walker.position[1])))
        for walker in self.walkers:
            s, direction = walker.next_s(dt_s)
            if robot_xy is not None:
                gap = self.robot_radius_m + walker.spec.radius_m + self.yield_gap_m
                ahead = walker.at(s)
                closer = math.dist(ahead, robot_xy) < math.dist(walker.position, robot_xy)
                if closer and math.dist(ahead, robot_xy) < gap:
                    walker.held_s += dt_s
                    if walker.held_s >= self.turn_back_s:
                        walker.direction, walker.held_s = -walker.direction, 0.0
                    continue
            walker.s_m, walker.direction, walker.held_s = s, direction, 0.0
        self._stamp_people()

    def _stamp_people(self) -> None:
        grid = self.grid
        flat = self.blocked.reshape(-1)
        flat[self._stamped] = self.static.reshape(-1)[self._stamped]
        cells: list[npt.NDArray[np.int64]] = []
        for walker in self.walkers:
            x, y = walker.position
            r = walker.spec.radius_m
            n = math.ceil(r / grid.resolution) + 1
            cx, cy = grid.world_to_cell(x, y)
            ix0, iy0 = int(cx), int(cy)
            ix, iy = np.meshgrid(np.arange(ix0 - n, ix0 + n + 1), np.arange(iy0 - n, iy0 + n + 1))
            wx, wy = grid.cell_to_world(ix, iy)
            keep = (np.hypot(wx - x, wy - y) <= r) & (ix >= 0) & (ix < grid.width)
            keep &= (iy >= 0) & (iy < grid.height)
            cells.append((iy[keep] * grid.width + ix[keep]).astype(np.int64))
        self._stamped = np.concatenate(cells) if cells else np.zeros(0, dtype=np.int64)
        flat[self._stamped] = True

    # -- the robot's safety ----------------------------------------------------------------
    def clearance_m(self, xy: FloatArray, *, people: bool = True) -> float:
        """Gap (m) between a round robot at ``xy`` and the nearest solid cell or person;
        <= 0 is a collision. Off the map counts as a collision."""
        grid = self.grid
        ix, iy = grid.world_to_cell(float(xy[0]), float(xy[1]))
        if not (0 <= ix < grid.width and 0 <= iy < grid.height):
            return -self.robot_radius_m
        gap = float(self._static_distance_m[int(iy), int(ix)]) - self.robot_radius_m
        for walker in self.walkers if people else ():
            d = math.dist(walker.position, (float(xy[0]), float(xy[1])))
            gap = min(gap, d - walker.spec.radius_m - self.robot_radius_m)
        return gap

    def is_free_for_robot(self, xy: tuple[float, float], margin_m: float = 0.05) -> bool:
        """Nothing static (walls, boxes, doors) within ``margin_m`` of the robot there."""
        return self.clearance_m(np.asarray(xy, dtype=float), people=False) > margin_m


def _segment_distance(
    x: FloatArray, y: FloatArray, a: tuple[float, float], b: tuple[float, float]
) -> FloatArray:
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length2 = dx * dx + dy * dy
    t = np.zeros_like(x) if length2 == 0 else ((x - ax) * dx + (y - ay) * dy) / length2
    t = np.clip(t, 0.0, 1.0)
    return np.asarray(np.hypot(x - (ax + t * dx), y - (ay + t * dy)))


def _distance_to_solid(solid: BoolArray) -> npt.NDArray[np.float64]:
    return map_transforms.distance_to(solid)
