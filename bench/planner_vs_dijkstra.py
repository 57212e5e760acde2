"""The planner against scipy's full single-source Dijkstra on the same graph, side by side in
one process: for each map, seeded start/goal pairs in the largest free component (15 per
seed, three seeds), the CPU time of ``GridPlanner.plan`` (A* in C where built, landmarks and
smoothing included), of the same planner without landmarks, of the A* search alone, and of
``scipy.sparse.csgraph.dijkstra`` from the same start over the whole map's graph (built once
beforehand, not timed; run before each plan, so every plan meets the caches a Dijkstra
left), and whether all found the same cost. The planner's set-up (labelling, landmarks) is
timed apart: once per map and cached on disk in the service.

Target (issue 26): the planner's median at most 0.3x the full Dijkstra's on every map (for
every seed's pairs).

Run: python bench/planner_vs_dijkstra.py [--pairs 15] [--seeds 7 8 9] [--maps office depot ...]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.ndimage import label
from scipy.sparse.csgraph import dijkstra

from assistantx.nav import grid_astar
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from assistantx.nav.planner import GridPlanner, PlannerParams, costmap_graph

REPO = Path(__file__).resolve().parents[1]
TARGET_RATIO = 0.3


def map_path(name: str) -> Path:
    return (
        REPO / "maps" / "office.yaml" if name == "office" else REPO / "maps/nav2" / f"{name}.yaml"
    )


def compare(name: str, pairs: int, seeds: list[int]) -> dict[str, object]:
    grid = load_map(map_path(name))
    costmap = Costmap.inflate(grid)
    params = PlannerParams()
    t0 = time.process_time()
    planner = GridPlanner(costmap, params)  # labelling and landmarks: once per map, reported
    planner.prepare()
    setup_s = time.process_time() - t0
    # The same search steered by the octile distance alone (the planner before landmarks),
    # side by side: each plan timed right after a full Dijkstra, as the caches then are.
    plain = GridPlanner(costmap, replace(params, landmarks=0))
    marks = planner.marks.marks if planner.marks is not None else (0, 0)
    # the search alone runs on what the planner searches: the landmarks' box of the costs
    height, width = costmap.costs.shape
    y0, y1, x0, x1 = (0, height, 0, width) if planner.marks is None else planner.marks.box
    box_costs = np.ascontiguousarray(costmap.costs[y0:y1, x0:x1])
    graph, ids = costmap_graph(costmap, params.cost_penalty)
    labels, _ = label(costmap.traversable)
    largest = int(np.argmax(np.bincount(labels.ravel())[1:])) + 1
    clear = np.argwhere((labels == largest) & (costmap.costs == 0))
    plan_s: list[float] = []
    plain_s: list[float] = []
    search_s: list[float] = []
    full_s: list[float] = []
    per_seed: list[float] = []
    worst_rel = 0.0
    for seed in seeds:
        rng = np.random.default_rng(seed)
        seed_plan: list[float] = []
        seed_full: list[float] = []
        for _ in range(pairs):
            a, b = clear[rng.integers(0, len(clear), 2)]
            start = tuple(float(v) for v in grid.cell_to_world(a[1], a[0]))
            goal = tuple(float(v) for v in grid.cell_to_world(b[1], b[0]))
            t0 = time.process_time()
            path = planner.plan((start[0], start[1]), (goal[0], goal[1]))
            seed_plan.append(time.process_time() - t0)
            if grid_astar.available():  # the search alone: no start/goal checks, no smoothing
                t0 = time.process_time()
                grid_astar.search(
                    box_costs,
                    grid.resolution,
                    params.cost_penalty,
                    (a[0] - y0, a[1] - x0),
                    (b[0] - y0, b[1] - x0),
                    marks,
                    (y0, x0, height, width),
                )
                search_s.append(time.process_time() - t0)
            t0 = time.process_time()
            dist = dijkstra(graph, indices=int(ids[a[0], a[1]]))
            seed_full.append(time.process_time() - t0)
            t0 = time.process_time()
            unsteered = plain.plan((start[0], start[1]), (goal[0], goal[1]))
            plain_s.append(time.process_time() - t0)
            t0 = time.process_time()
            dijkstra(graph, indices=int(ids[a[0], a[1]]))
            seed_full.append(time.process_time() - t0)
            reference = float(dist[ids[b[0], b[1]]])
            for cost in (path.cost, unsteered.cost):
                worst_rel = max(worst_rel, abs(cost - reference) / max(reference, 1e-12))
        per_seed.append(statistics.median(seed_plan) / statistics.median(seed_full))
        plan_s += seed_plan
        full_s += seed_full
    plan_ms, full_ms = statistics.median(plan_s) * 1e3, statistics.median(full_s) * 1e3
    return {
        "map": name,
        "cells": int(costmap.costs.size),
        "pairs": pairs * len(seeds),
        "seeds": seeds,
        "planner_setup_ms": round(setup_s * 1e3, 1),
        "landmarks": params.landmarks if planner.marks is not None else 0,
        "plan_median_ms": round(plan_ms, 2),
        "plan_max_ms": round(max(plan_s) * 1e3, 1),
        "dijkstra_median_ms": round(full_ms, 2),
        "ratio": round(plan_ms / full_ms, 3),
        "ratio_per_seed": [round(r, 3) for r in per_seed],
        "plain_ratio": round(statistics.median(plain_s) * 1e3 / full_ms, 3),
        "search_only_ratio": round(statistics.median(search_s) * 1e3 / full_ms, 3)
        if search_s
        else None,
        "max_cost_rel_diff": worst_rel,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=15, help="pairs per seed")
    parser.add_argument("--seeds", type=int, nargs="+", default=[7, 8, 9])
    parser.add_argument(
        "--maps", nargs="+", default=["office", "depot", "warehouse", "tb3_sandbox"]
    )
    args = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.1f} at the start")
    rows = []
    for name in args.maps:
        row = compare(name, args.pairs, args.seeds)
        rows.append(row)
        print(
            f"{name:12} plan median {row['plan_median_ms']:7.2f} ms (max {row['plan_max_ms']})"
            f"  full Dijkstra {row['dijkstra_median_ms']:7.2f} ms  ratio {row['ratio']}"
            f" (per seed {row['ratio_per_seed']}; without landmarks {row['plain_ratio']};"
            f" search alone {row['search_only_ratio']})  set-up {row['planner_setup_ms']} ms"
            f"  cost diff {row['max_cost_rel_diff']:.1e}"
        )
    ok = all(
        max(r["ratio_per_seed"]) <= TARGET_RATIO  # type: ignore[call-overload]
        and float(str(r["max_cost_rel_diff"])) <= 1e-9
        for r in rows
    )
    summary = {
        "compiled_search": grid_astar.available(),
        "load_average": [round(v, 1) for v in os.getloadavg()],
        "maps": rows,
        "all_ok": ok,
    }
    print(json.dumps(summary))


if __name__ == "__main__":
    main()
