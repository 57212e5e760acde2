"""Random poses and anchor-to-anchor tours for the robot benchmarks (AMCL on the office map,
the real-map tour): one place for how a trial picks where the robot starts and where it drives."""

from __future__ import annotations

import math

import numpy as np

from assistantx.core.errors import RobotError
from assistantx.nav.anchors import Anchor
from assistantx.nav.diff_drive import PurePursuit
from assistantx.nav.occupancy_map import OccupancyMap
from assistantx.nav.planner import GridPlanner

TOUR_LENGTH_M = 40.0


class TourWorld:
    """A map, its anchors, a planner and the free cells (``clear``: rows of (iy, ix)) a trial
    may start in; subclasses fill them."""

    grid: OccupancyMap
    anchors: list[Anchor]
    planner: GridPlanner
    clear: np.ndarray

    def random_pose(self, rng: np.random.Generator) -> np.ndarray:
        iy, ix = self.clear[rng.integers(0, len(self.clear))]
        x, y = self.grid.cell_to_world(ix, iy)
        return np.array([float(x), float(y), rng.uniform(-math.pi, math.pi)])

    def route(self, start: np.ndarray, rng: np.random.Generator) -> PurePursuit:
        """A path from ``start`` through random anchors, long enough for the trial (an anchor
        the planner cannot reach from here is skipped)."""
        points = [start[:2]]
        here = (float(start[0]), float(start[1]))
        total = 0.0
        while total < TOUR_LENGTH_M:
            goal = self.anchors[int(rng.integers(0, len(self.anchors)))]
            try:
                path = self.planner.plan(here, (goal.x, goal.y))
            except RobotError:
                continue
            points.append(path.resampled(0.05))
            total += path.length_m
            here = (goal.x, goal.y)
        return PurePursuit(np.vstack(points), None)
