"""Safety in simulation: a collision monitor on the robot's own scan, and the record of how
close the robot came to things in the world.

The monitor is nav2's collision_monitor "stop" polygon: a rectangle ahead of (or behind,
when reversing) a round robot, as wide as the robot plus a margin and as long as the robot's
radius plus ``stop_gap_m`` plus the distance one control tick covers. Any scan point inside
it stops the translation (turning on the spot stays allowed: the base is round). It reads a
short-range scan from the robot's sensor, taken every control tick, so a person stepping
out in front is seen before the next filter update.

``SafetyRecord`` counts events, not ticks: a collision is an entry into contact (clearance
<= 0), a near miss an entry into clearance < ``near_miss_m`` that did not become contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from assistantx.nav.geometry import FloatArray


@dataclass(frozen=True)
class MonitorParams:
    stop_gap_m: float = 0.05  # keep this far from anything ahead (plus one tick of travel)
    side_margin_m: float = 0.05  # the polygon's half-width is robot radius + this
    range_m: float = 1.2  # the short-range scan the monitor reads
    near_miss_m: float = 0.10


def translation_blocked(
    ranges: FloatArray,
    angles: FloatArray,
    v: float,
    dt_s: float,
    robot_radius_m: float,
    params: MonitorParams,
) -> bool:
    """Whether a scan point (robot frame) lies in the stop rectangle for speed ``v``."""
    if v == 0.0:
        return False
    x = ranges * np.cos(angles) * math.copysign(1.0, v)
    y = ranges * np.sin(angles)
    reach = robot_radius_m + params.stop_gap_m + abs(v) * dt_s
    inside = (x > 0.0) & (x <= reach) & (np.abs(y) <= robot_radius_m + params.side_margin_m)
    return bool(inside.any())


@dataclass
class SafetyRecord:
    near_miss_m: float = 0.10
    collisions: int = 0
    near_misses: int = 0
    min_clearance_m: float = math.inf
    stops: int = 0  # ticks the monitor held the robot
    collision_points: list[tuple[float, float]] = field(default_factory=list)
    _in_contact: bool = False
    _in_near_miss: bool = False

    def observe(self, clearance_m: float, xy: FloatArray) -> None:
        self.min_clearance_m = min(self.min_clearance_m, clearance_m)
        contact = clearance_m <= 0.0
        near = clearance_m < self.near_miss_m
        if contact and not self._in_contact:
            self.collisions += 1
            self.collision_points.append((float(xy[0]), float(xy[1])))
        elif near and not self._in_near_miss and not contact:
            self.near_misses += 1
        self._in_contact, self._in_near_miss = contact, near
