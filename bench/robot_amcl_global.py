"""Global localization and kidnapped-robot recovery on the office map (seeded trials), with
the robot moving while it localizes (bench/_active_trials.py: it turns in place, then drives
short legs into free space picked from its scan, until the cloud has converged, or says it
is not localized).

A trial succeeds only when the robot declared a pose, that pose is within 0.25 m and 10 deg
of the TRUE pose, and it stays so for the next 10 updates of driving. Kidnapped: the robot
tracks for 20 updates, is carried elsewhere without the odometry noticing, drives on until
it notices (LostWatch), then localizes again.

Run: python bench/robot_amcl_global.py [--trials N]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
from _active_trials import global_trial, kidnap_trial
from _tours import TourWorld

from assistantx.nav.anchors import load_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.lidar import Lidar
from assistantx.nav.occupancy_map import load_map
from assistantx.nav.planner import GridPlanner

REPO = Path(__file__).resolve().parents[1]
TRIALS = 20


class World(TourWorld):
    def __init__(self) -> None:
        self.grid = load_map(REPO / "maps" / "office.yaml")
        self.anchors = list(load_anchors(REPO / "maps" / "office.anchors.yaml").values())
        self.costmap = Costmap.inflate(self.grid)
        self.planner = GridPlanner(self.costmap)
        self.lidar = Lidar(self.grid)
        self.clear = np.argwhere(self.costmap.costs == 0)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=TRIALS)
    trials = parser.parse_args().trials
    world = World()
    started = time.process_time()
    results: dict[str, object] = {"trials": trials}
    for kind, run, seed0 in (("global", global_trial, 1000), ("kidnap", kidnap_trial, 2000)):
        outcomes = []
        for i in range(trials):
            t = run(world, seed0 + i)
            outcomes.append(t)
            print(
                f"{kind} trial {i:2d}: {'ok' if t.success else 'FAILED'}"
                f"{'' if t.localized else ' (said: not localized)'} after {t.updates} "
                f"updates, {t.distance_m:.1f} m driven",
                flush=True,
            )
        ok = [t for t in outcomes if t.success]
        results[f"{kind}_success"] = len(ok)
        results[f"{kind}_not_localized"] = sum(not t.localized for t in outcomes)
        results[f"{kind}_median_updates"] = (
            float(np.median([t.updates for t in ok])) if ok else None
        )
    results["cpu_s"] = round(time.process_time() - started, 1)
    results["all_ok"] = results["global_success"] == trials and results["kidnap_success"] == trials
    print(json.dumps(results))


if __name__ == "__main__":
    main()
