"""The robot base on real buildings' maps (ROS map_server YAML + image).

Default: the three nav2 maps in ``<repo>/maps/nav2`` (depot, warehouse, tb3_sandbox).
``--map YAML`` runs one map instead; ``--anchors YAML`` gives its anchors, otherwise
``--anchor-count`` anchors are placed, seeded, in free space the robot can reach from all
of them (assistantx.nav.anchor_check.place_anchors). Per map:

- set-up: loading the map, the inflated costmap, the planner's labels and AMCL's likelihood
  field (the work a robot does before its first move), wall seconds;
- planner: a plan between every ordered pair of anchors (they are mutually reachable, so
  every pair must succeed), median and max seconds per plan;
- tour: the robot with default parameters (AMCL on, LiDAR, obstacle layer) drives a seeded
  tour of ``--legs`` legs between random anchors; legs_failed counts RobotErrors, the
  position errors compare the AMCL estimate with the truth at every filter update;
- global localization and kidnapped-robot recovery, 20 seeded trials each, as
  bench/_active_trials.py runs them (the robot turns and drives short legs while it
  localizes; success only when the pose it declares is the true one, within 0.25 m and
  10 deg, and stays so), on random poses of the reachable free space; ``*_not_localized``
  counts the trials that ended saying so, ``*_wrong_pose_declared`` those that declared a
  wrong pose; of the failures, ``*_failed_on_lookalike_pose`` counts those whose final
  estimate sees the map as the true pose does (median beam difference < 5 cm);
- peak_rss_mb: the process's peak resident memory after the map (it only grows).

Last stdout line: one JSON object, ``{"maps": {name: {...}}, "all_ok": bool}``.
Run: python bench/robot_real_maps.py [--map YAML --anchors YAML] [--legs N] [--trials N]

``--scenario FILE`` (repeatable; maps/scenarios/*.yaml) instead drives each scenario's legs in
its simulated world (the map plus what changed, people walking; bench/_scenario_run.py) and
reports legs driven or reported, collisions, near misses (< 10 cm), detours, the share of
returns on unmapped things and the position error under change; ``--png FILE`` draws the
first scenario's run (map, changes, paths, people). Last line:
``{"scenarios": {name: {...}}, "all_ok": bool}``, all_ok when every leg went as the file
expects, nothing was touched and the p95 error is at most 10 cm.
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from _scenario_run import run_scenario
from _tours import TourWorld
from scipy.ndimage import label

from assistantx.core.errors import RobotError
from assistantx.nav.amcl import LikelihoodField
from assistantx.nav.anchor_check import check_anchors, place_anchors
from assistantx.nav.anchors import Anchor, load_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.lidar import Lidar, cast_rays
from assistantx.nav.navigation import NavigationParams, Navigator, shared_planner
from assistantx.nav.occupancy_map import OccupancyMap, load_map
from assistantx.nav.scenario import load_scenario

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _active_trials import global_trial, kidnap_trial

REPO = Path(__file__).resolve().parents[1]
# The three nav2 maps are committed in the repository (maps/nav2, Apache-2.0).
SHARED_MAPS = REPO / "maps" / "nav2"
DEFAULT_MAPS = ("depot", "warehouse", "tb3_sandbox")


class RealWorld(TourWorld):
    """What run_filter needs: the map, a LiDAR, a planner and random reachable poses."""

    def __init__(self, grid: OccupancyMap, anchors: dict[str, Anchor]) -> None:
        params = NavigationParams()
        self.grid = grid
        self.anchors = list(anchors.values())
        self.planner = shared_planner(grid, params.inflation, params.planner)
        self.costmap = self.planner.costmap
        self.lidar = Lidar(grid, params.lidar)
        labels = _reachable(self.costmap, anchors)
        self.clear = np.argwhere(labels & (self.costmap.costs == 0))


def _reachable(costmap: Costmap, anchors: dict[str, Anchor]) -> np.ndarray:
    """Cells the robot can reach from the anchors (they are mutually reachable)."""
    labels, _ = label(costmap.traversable)
    a = next(iter(anchors.values()))
    ix, iy = costmap.grid.world_to_cell(a.x, a.y)
    return np.asarray(labels == labels[int(iy), int(ix)])


def setup(grid_yaml: Path) -> tuple[OccupancyMap, float]:
    started = time.perf_counter()
    grid = load_map(grid_yaml)
    params = NavigationParams()
    shared_planner(grid, params.inflation, params.planner)
    LikelihoodField(grid, params.amcl)
    return grid, time.perf_counter() - started


def planner_pairs(world: RealWorld, anchors: dict[str, Anchor]) -> dict[str, object]:
    times, failures = [], []
    for a, sa in anchors.items():
        for b, sb in anchors.items():
            if a == b:
                continue
            started = time.perf_counter()
            try:
                world.planner.plan((sa.x, sa.y), (sb.x, sb.y))
            except RobotError as exc:
                failures.append(f"{a}->{b}: {exc}")
            times.append(time.perf_counter() - started)
    return {
        "planner_pairs": len(times),
        "planner_success": len(times) - len(failures),
        "planner_failures": failures[:5],
        "planning_median_s": round(statistics.median(times), 4),
        "planning_max_s": round(max(times), 4),
    }


def tour(grid: OccupancyMap, anchors: dict[str, Anchor], legs: int, seed: int) -> dict[str, object]:
    rng = np.random.default_rng(seed)
    names = list(anchors)
    here = names[int(rng.integers(len(names)))]
    first = anchors[here]
    nav = Navigator(grid, np.array([first.x, first.y, first.yaw]), np.random.default_rng(seed + 1))
    failed: list[str] = []
    arrival = []
    started = time.perf_counter()
    for _ in range(legs):
        there = names[int(rng.integers(len(names) - 1))]
        there = names[-1] if there == here else there
        goal = anchors[there]
        try:
            for _seconds in nav.follow(nav.plan((goal.x, goal.y)), goal.yaw):
                pass
            true = nav.base.true_pose
            arrival.append(math.hypot(true[0] - goal.x, true[1] - goal.y))
        except RobotError as exc:
            failed.append(f"{here}->{there}: {exc}")
        here = there
    pos = np.array([math.dist(s.true_pose[:2], s.estimate[:2]) for s in nav.tracking])
    return {
        "legs": legs,
        "legs_failed": len(failed),
        "leg_failures": failed[:5],
        "distance_m": round(nav.base.odometer_m, 1),
        "mean_position_error_m": round(float(pos.mean()), 4) if pos.size else None,
        "p95_position_error_m": round(float(np.percentile(pos, 95)), 4) if pos.size else None,
        "max_position_error_m": round(float(pos.max()), 4) if pos.size else None,
        "mean_arrival_error_m": round(float(np.mean(arrival)), 4) if arrival else None,
        "obstacle_marks_left": len(nav.obstacles),
        "tour_wall_s": round(time.perf_counter() - started, 1),
    }


LOOKALIKE_M = 0.05  # median beam difference below the LiDAR's noise: the map looks the same


def looks_alike(world: RealWorld, estimate: np.ndarray | None, true_pose: np.ndarray) -> bool:
    """Whether the map, seen from the final (wrong) estimate, gives the scan it gives from
    the true pose: noise-free ranges of every beam within LOOKALIKE_M (median)."""
    if estimate is None:
        return False
    blocked, grid, lidar = world.grid.obstacles, world.grid, world.lidar
    seen = cast_rays(blocked, grid, true_pose, lidar.angles, lidar.params.max_range_m)
    other = cast_rays(blocked, grid, estimate, lidar.angles, lidar.params.max_range_m)
    return bool(np.median(np.abs(seen - other)) < LOOKALIKE_M)


def localization(world: RealWorld, trials: int) -> dict[str, object]:
    """Successes (bench/_active_trials.py: the robot moves while it localizes, and a trial
    counts only if the pose it declared is the true one), the trials that ended saying
    "not localized", and of the failures those that ended on a look-alike pose."""
    out: dict[str, object] = {"trials": trials}
    for kind, run, seed0 in (("global", global_trial, 1000), ("kidnap", kidnap_trial, 2000)):
        results = [run(world, seed0 + i) for i in range(trials)]  # type: ignore[arg-type]
        ok = [t for t in results if t.success]
        out[f"{kind}_success"] = len(ok)
        out[f"{kind}_not_localized"] = sum(not t.localized for t in results)
        out[f"{kind}_wrong_pose_declared"] = sum(t.localized and not t.success for t in results)
        out[f"{kind}_failed_on_lookalike_pose"] = sum(
            not t.success and looks_alike(world, t.final_pose, t.true_pose) for t in results
        )
        out[f"{kind}_median_updates"] = float(np.median([t.updates for t in ok])) if ok else None
        out[f"{kind}_max_updates"] = max((t.updates for t in ok), default=None)
        out[f"{kind}_median_drive_m"] = (
            round(float(np.median([t.distance_m for t in ok])), 1) if ok else None
        )
    return out


def run_map(
    map_yaml: Path, anchors_yaml: Path | None, args: argparse.Namespace
) -> dict[str, object]:
    grid, setup_s = setup(map_yaml)
    params = NavigationParams()
    costmap = shared_planner(grid, params.inflation, params.planner).costmap
    if anchors_yaml is not None:
        anchors = load_anchors(anchors_yaml)
        problems = check_anchors(costmap, anchors)
        if problems:
            raise SystemExit(f"{anchors_yaml}: {problems[0].anchor}: {problems[0].problem}")
    else:
        anchors = place_anchors(costmap, args.anchor_count, np.random.default_rng(args.seed))
    world = RealWorld(grid, anchors)
    result: dict[str, object] = {
        "size_m": [round(v, 1) for v in grid.size_m],
        "cells": grid.width * grid.height,
        "anchors": len(anchors),
        "setup_s": round(setup_s, 3),
    }
    result |= planner_pairs(world, anchors)
    result |= tour(grid, anchors, args.legs, args.seed)
    if args.trials:
        result |= localization(world, args.trials)
    result["peak_rss_mb"] = round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1)
    return result


def passed(r: dict[str, object], trials: int) -> bool:
    ok = (
        r["legs_failed"] == 0
        and r["planner_success"] == r["planner_pairs"]
        and r["mean_position_error_m"] is not None
        and float(r["mean_position_error_m"]) <= 0.03  # type: ignore[arg-type]
        and float(r["p95_position_error_m"]) <= 0.08  # type: ignore[arg-type]
    )
    if trials:
        ok = ok and r["global_success"] == trials and r["kidnap_success"] == trials
    return bool(ok)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", type=Path, help="a map_server YAML (default: the three real maps)")
    parser.add_argument("--anchors", type=Path, help="its anchors YAML (default: placed)")
    parser.add_argument("--anchor-count", type=int, default=8)
    parser.add_argument("--legs", type=int, default=16)
    parser.add_argument("--trials", type=int, default=20)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scenario", type=Path, action="append", help="a scenario YAML")
    parser.add_argument("--png", type=Path, help="with --scenario: draw the first run here")
    args = parser.parse_args()
    if args.scenario:
        scenarios(args.scenario, args.png)
        return
    if args.anchors and not args.map:
        parser.error("--anchors needs --map")
    maps = (
        [(args.map.stem, args.map, args.anchors)]
        if args.map
        else [(name, SHARED_MAPS / f"{name}.yaml", None) for name in DEFAULT_MAPS]
    )
    results: dict[str, dict[str, object]] = {}
    for name, yaml_path, anchors_yaml in maps:
        started = time.perf_counter()
        r = run_map(yaml_path, anchors_yaml, args)
        r["wall_s"] = round(time.perf_counter() - started, 1)
        results[name] = r
        print(
            f"{name}: set-up {r['setup_s']} s; planner {r['planner_success']}/"
            f"{r['planner_pairs']} pairs, median {r['planning_median_s']} s; tour "
            f"{r['legs'] - r['legs_failed']}/{r['legs']} legs, error mean "
            f"{r['mean_position_error_m']} m p95 {r['p95_position_error_m']} m; global "
            f"{r.get('global_success')}/{args.trials} (not localized "
            f"{r.get('global_not_localized')}, wrong pose {r.get('global_wrong_pose_declared')}, "
            f"median {r.get('global_median_updates')} updates), kidnap "
            f"{r.get('kidnap_success')}/{args.trials} (not localized "
            f"{r.get('kidnap_not_localized')}, wrong pose {r.get('kidnap_wrong_pose_declared')},"
            f" median {r.get('kidnap_median_updates')} updates); "
            f"peak {r['peak_rss_mb']} MB; {r['wall_s']} s",
            flush=True,
        )
        if r["leg_failures"]:
            print(f"  failed legs: {r['leg_failures']}", flush=True)
    all_ok = all(passed(r, args.trials) for r in results.values())
    print(json.dumps({"maps": results, "all_ok": all_ok}))


def scenarios(paths: list[Path], png: Path | None) -> None:
    results: dict[str, dict[str, object]] = {}
    for i, path in enumerate(paths):
        r = run_scenario(load_scenario(path), png if i == 0 else None)
        results[str(r["scenario"])] = r
        print(
            f"{r['scenario']} ({r['map']}): {r['legs_driven']} legs driven, "
            f"{r['legs_reported']} reported ({r['legs_as_expected']}/{r['legs']} as expected), "
            f"{r['distance_m']} m; collisions {r['collisions']}, near misses "
            f"{r['near_misses']}, detours {r['detours']}; {r['unmapped_return_share']:.0%} of "
            f"returns unmapped, error mean {r['mean_position_error_m']} m p95 "
            f"{r['p95_position_error_m']} m; {r['cpu_s']} CPU s",
            flush=True,
        )
        for leg in r["per_leg"]:  # type: ignore[attr-defined]
            if leg["said"]:
                print(f"  {leg['leg']}: {leg['outcome']}: {leg['said']}", flush=True)
    all_ok = all(
        r["legs_as_expected"] == r["legs"]
        and r["collisions"] == 0
        and float(r["p95_position_error_m"]) <= 0.10  # type: ignore[arg-type]
        for r in results.values()
    )
    print(json.dumps({"scenarios": results, "all_ok": all_ok}))


if __name__ == "__main__":
    main()
