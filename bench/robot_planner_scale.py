"""Planning on a big building: set-up time and memory of the costmap and planner, and plans
across it, on a generated 175 x 142 m floor at 0.05 m (3500 x 2840 cells).

The floor: 10 m rooms in a grid, walls 0.15 m thick, a 1.2 m door in each wall of each room,
a 5 m strip of unknown space along the east side (outside the scan). Set-up is what a robot
does before its first plan (inflate the map, label the reachable regions); ``setup_rss_mb``
is the process's peak resident memory after it. Then ``--plans`` seeded plans between
random free cells (straight line >= 3 m), in this process: their median and max seconds
and the peak memory after them (``peak_rss_mb``; a plan's memory grows with the free area
of the region it searches, so the longest plans set it).

Run: python bench/robot_planner_scale.py [--plans N]
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import statistics
import time

import numpy as np

from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import FREE, OCCUPIED, UNKNOWN, OccupancyMap
from assistantx.nav.planner import GridPlanner

RES = 0.05
ROOM = 200  # cells (10 m)
WALL = 3  # cells
DOOR = (80, 104)  # cells along the wall (1.2 m)


def building() -> OccupancyMap:
    height, width = 2840, 3500
    data = np.full((height, width), FREE, dtype=np.int8)
    for y in range(0, height, ROOM):
        data[y : y + WALL, :] = OCCUPIED
    for x in range(0, width, ROOM):
        data[:, x : x + WALL] = OCCUPIED
    data[-WALL:, :] = OCCUPIED
    data[:, -WALL:] = OCCUPIED
    for y in range(0, height, ROOM):
        for x in range(0, width, ROOM):
            if y:
                data[y : y + WALL, x + DOOR[0] : x + DOOR[1]] = FREE
            if x:
                data[y + DOOR[0] : y + DOOR[1], x : x + WALL] = FREE
    data[:, width - 100 :] = UNKNOWN
    return OccupancyMap(data, RES)


def rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plans", type=int, default=12)
    parser.add_argument("--seed", type=int, default=3)
    args = parser.parse_args()
    grid = building()
    loaded_rss = rss_mb()
    started = time.perf_counter()
    planner = GridPlanner(Costmap.inflate(grid))
    planner.prepare()  # its landmarks: set-up, not the first plan
    setup_s = time.perf_counter() - started
    setup_rss = rss_mb()
    rng = np.random.default_rng(args.seed)
    free = np.argwhere(planner.costmap.costs == 0)
    times, straight = [], []
    while len(times) < args.plans:
        a, b = free[rng.integers(0, len(free), 2)]
        start = tuple(float(v) for v in grid.cell_to_world(a[1], a[0]))
        goal = tuple(float(v) for v in grid.cell_to_world(b[1], b[0]))
        if math.dist(start, goal) < 3.0:
            continue
        t0 = time.perf_counter()
        path = planner.plan((start[0], start[1]), (goal[0], goal[1]))
        times.append(time.perf_counter() - t0)
        straight.append(math.dist(start, goal))
        print(
            f"plan {math.dist(start, goal):6.1f} m straight, cost {path.cost:6.1f}: "
            f"{times[-1]:.2f} s, peak {rss_mb():.0f} MB",
            flush=True,
        )
    result = {
        "size_m": [round(v, 1) for v in grid.size_m],
        "cells": grid.width * grid.height,
        "traversable_cells": int(planner.costmap.traversable.sum()),
        "loaded_rss_mb": round(loaded_rss, 1),
        "setup_s": round(setup_s, 3),
        "setup_rss_mb": round(setup_rss, 1),
        "plans": len(times),
        "longest_straight_m": round(max(straight), 1),
        "plan_median_s": round(statistics.median(times), 3),
        "plan_max_s": round(max(times), 3),
        "peak_rss_mb": round(rss_mb(), 1),
    }
    print(json.dumps(result))


if __name__ == "__main__":
    main()
