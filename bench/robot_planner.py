"""Planning on the office map: 100 seeded random start/goal pairs at least 3 m apart,
split into room-to-room (straight line < 12 m) and across-the-floor (>= 12 m) queries.

Run: python bench/robot_planner.py
"""

from __future__ import annotations

import json
import math
import statistics
import time
from pathlib import Path

import numpy as np

from assistantx.core.errors import UnreachableError
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from assistantx.nav.planner import GridPlanner

REPO = Path(__file__).resolve().parents[1]
PAIRS = 100
MIN_APART_M = 3.0
ACROSS_M = 12.0


def main() -> None:
    grid = load_map(REPO / "maps" / "office.yaml")
    started = time.perf_counter()
    costmap = Costmap.inflate(grid)
    planner = GridPlanner(costmap)
    planner.prepare()  # its landmarks: set-up, not the first plan
    setup_s = time.perf_counter() - started
    rng = np.random.default_rng(2024)
    free = np.argwhere(costmap.costs == 0)  # cells clear of inflation: valid starts and goals
    queries = []
    while len(queries) < PAIRS:
        a, b = free[rng.integers(0, len(free), 2)]
        start = grid.cell_to_world(a[1], a[0])
        goal = grid.cell_to_world(b[1], b[0])
        start_xy, goal_xy = (float(start[0]), float(start[1])), (float(goal[0]), float(goal[1]))
        if math.dist(start_xy, goal_xy) >= MIN_APART_M:
            queries.append((start_xy, goal_xy))
    near_ms, far_ms, lengths, costs, ratios = [], [], [], [], []
    failures = 0
    for start_xy, goal_xy in queries:
        t0 = time.perf_counter()
        try:
            path = planner.plan(start_xy, goal_xy)
        except UnreachableError:
            failures += 1
            continue
        elapsed_ms = (time.perf_counter() - t0) * 1000
        straight = math.dist(start_xy, goal_xy)
        (far_ms if straight >= ACROSS_M else near_ms).append(elapsed_ms)
        lengths.append(path.length_m)
        costs.append(path.cost)
        ratios.append(path.length_m / straight)
    result = {
        "pairs": PAIRS,
        "success_rate": (PAIRS - failures) / PAIRS,
        "setup_s": round(setup_s, 3),
        "room_to_room_pairs": len(near_ms),
        "room_to_room_median_ms": round(statistics.median(near_ms), 2),
        "room_to_room_p95_ms": round(float(np.percentile(near_ms, 95)), 2),
        "across_floor_pairs": len(far_ms),
        "across_floor_median_ms": round(statistics.median(far_ms), 2),
        "across_floor_p95_ms": round(float(np.percentile(far_ms, 95)), 2),
        "mean_path_length_m": round(statistics.fmean(lengths), 2),
        "mean_path_cost": round(statistics.fmean(costs), 2),
        "mean_length_over_straight_line": round(statistics.fmean(ratios), 3),
    }
    print(f"costmap + graph setup: {setup_s:.3f} s ({len(free)} clear cells)")
    print(f"success: {result['success_rate']:.0%} of {PAIRS} pairs >= {MIN_APART_M} m apart")
    print(
        f"room to room (<{ACROSS_M} m, n={len(near_ms)}): median "
        f"{result['room_to_room_median_ms']} ms, p95 {result['room_to_room_p95_ms']} ms"
    )
    print(
        f"across the floor (n={len(far_ms)}): median {result['across_floor_median_ms']} ms, "
        f"p95 {result['across_floor_p95_ms']} ms"
    )
    print(
        f"path length {result['mean_path_length_m']} m on average "
        f"({result['mean_length_over_straight_line']}x the straight line), "
        f"cost {result['mean_path_cost']}"
    )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
