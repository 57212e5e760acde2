"""Tracking accuracy of AMCL with default (nav2) parameters over a seeded 200 m tour of all
the office anchors: the robot plans, drives by pure pursuit on its *estimated* pose, and the
estimate is compared with the true pose at every filter update.

Run: python bench/robot_amcl_tracking.py
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from assistantx.nav.anchors import load_anchors
from assistantx.nav.geometry import angle_diff
from assistantx.nav.navigation import Navigator
from assistantx.nav.occupancy_map import load_map

REPO = Path(__file__).resolve().parents[1]
TOUR_M = 200.0
DIVERGED_M = 0.5


def main() -> None:
    grid = load_map(REPO / "maps" / "office.yaml")
    anchors = load_anchors(REPO / "maps" / "office.anchors.yaml")
    rng = np.random.default_rng(8)
    # A seeded tour: a random first anchor, then always the nearest unvisited one, round
    # and round until at least 200 m are driven and every anchor has been visited.
    names = list(anchors)
    order = [names[int(rng.integers(len(names)))]]
    while len(order) < len(names):
        here = anchors[order[-1]]
        rest = [n for n in names if n not in order]
        order.append(
            min(rest, key=lambda n: math.dist((here.x, here.y), (anchors[n].x, anchors[n].y)))
        )
    first = anchors[order[0]]
    nav = Navigator(grid, np.array([first.x, first.y, first.yaw]), np.random.default_rng(9))
    started = time.perf_counter()
    visited, arrival_errors = 0, []
    stops = order[1:] + order[:1]
    while nav.base.odometer_m < TOUR_M or visited < len(names):
        goal = anchors[stops[visited % len(stops)]]
        for _ in nav.follow(nav.plan((goal.x, goal.y)), goal.yaw):
            pass
        visited += 1
        true = nav.base.true_pose
        arrival_errors.append(math.hypot(true[0] - goal.x, true[1] - goal.y))
    wall = time.perf_counter() - started
    pos = np.array([math.dist(s.true_pose[:2], s.estimate[:2]) for s in nav.tracking])
    yaw = np.degrees([abs(float(angle_diff(s.true_pose[2], s.estimate[2]))) for s in nav.tracking])
    result = {
        "distance_m": round(nav.base.odometer_m, 1),
        "anchors_visited": visited,
        "filter_updates": len(pos),
        "mean_position_error_m": round(float(pos.mean()), 4),
        "p95_position_error_m": round(float(np.percentile(pos, 95)), 4),
        "max_position_error_m": round(float(pos.max()), 4),
        "mean_heading_error_deg": round(float(yaw.mean()), 3),
        "p95_heading_error_deg": round(float(np.percentile(yaw, 95)), 3),
        "diverged": bool(pos.max() > DIVERGED_M),
        "mean_arrival_error_m": round(float(np.mean(arrival_errors)), 4),
        "simulated_s": round(nav.base.time_s, 1),
        "wall_s": round(wall, 2),
    }
    print(f"tour: {result['distance_m']} m, {visited} anchors, {len(pos)} filter updates")
    print(
        f"position error: mean {result['mean_position_error_m'] * 100:.1f} cm, "
        f"p95 {result['p95_position_error_m'] * 100:.1f} cm, "
        f"max {result['max_position_error_m'] * 100:.1f} cm"
    )
    print(
        f"heading error: mean {result['mean_heading_error_deg']:.2f} deg, "
        f"p95 {result['p95_heading_error_deg']:.2f} deg; diverged: {result['diverged']}"
    )
    print(f"arrival error at anchors: mean {result['mean_arrival_error_m'] * 100:.1f} cm")
    print(f"simulated {result['simulated_s']} s of driving in {result['wall_s']} s")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
