"""Fleet throughput: the same 60 instructions served by 1, 2 and 3 robot bases on the office
map (assistantx.nav.fleet: soonest-finish assignment, block reservations so robots yield).

Each instruction is one trip: drive to where the item is (a desk or facility), dwell 20 s for
the hand-over, drive to the requester's desk, dwell 20 s. Releases are seeded, on average one
every ``--gap`` seconds, busier than one robot can keep up with. Per fleet size: instructions
per hour (60 over the time from the first release to the last finish), the mean wait (from
release to the requester's hand-over, i.e. the trip's end), the mean time robots spent yielding
to each other, and the speed-up over one robot. Simulated time, not wall time.

Last stdout line: one JSON object. Run: python bench/fleet.py [--gap S] [--seed N]
"""

from __future__ import annotations

import argparse
import json
import statistics
from pathlib import Path

import numpy as np

from assistantx.nav.anchors import load_anchors
from assistantx.nav.fleet import Dispatcher, Trip, serve
from assistantx.nav.navigation import NavigationParams, shared_planner
from assistantx.nav.occupancy_map import load_map

REPO = Path(__file__).resolve().parents[1]
HOMES = ("desk_01", "desk_16", "desk_08")


def instructions(names: list[str], anchors: dict, n: int, gap_s: float, seed: int) -> list[Trip]:
    rng = np.random.default_rng(seed)
    trips, t = [], 0.0
    for i in range(n):
        src, dst = rng.choice(len(names), 2, replace=False)
        a, b = anchors[names[int(src)]], anchors[names[int(dst)]]
        trips.append(Trip(f"i{i:02d}", t, ((a.x, a.y), (b.x, b.y))))
        t += float(rng.exponential(gap_s))
    return trips


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=60)
    parser.add_argument("--gap", type=float, default=30.0)
    parser.add_argument("--seed", type=int, default=11)
    args = parser.parse_args()
    grid = load_map(REPO / "maps" / "office.yaml")
    anchors = load_anchors(REPO / "maps" / "office.anchors.yaml")
    params = NavigationParams()
    planner = shared_planner(grid, params.inflation, params.planner)
    names = sorted(anchors)
    trips = instructions(names, anchors, args.count, args.gap, args.seed)
    results: dict[str, dict[str, float]] = {}
    for size in (1, 2, 3):
        robots = {
            f"robot {k + 1}": (anchors[h].x, anchors[h].y) for k, h in enumerate(HOMES[:size])
        }
        done = serve(Dispatcher(planner, robots), trips)
        span = max(a.finish_s for a in done) - min(t.release_s for t in trips)
        waits = [
            a.finish_s - t.release_s
            for a, t in zip(done, sorted(trips, key=lambda t: t.release_s), strict=True)
        ]
        results[str(size)] = {
            "instructions_per_hour": round(len(done) / span * 3600, 1),
            "mean_wait_s": round(statistics.mean(waits), 1),
            "mean_yield_s": round(statistics.mean(a.yielded_s for a in done), 2),
            "trips_per_robot": [sum(a.robot == r for a in done) for r in robots],  # type: ignore[dict-item]
        }
        print(f"{size} robot(s): {results[str(size)]}", flush=True)
    base = results["1"]["instructions_per_hour"]
    for size in ("2", "3"):
        results[size]["speedup"] = round(results[size]["instructions_per_hour"] / base, 2)
    print(
        json.dumps({"fleet": results, "two_robots_at_least_1_6x": results["2"]["speedup"] >= 1.6})
    )


if __name__ == "__main__":
    main()
