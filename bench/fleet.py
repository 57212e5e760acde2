"""Fleet throughput, driven for real: the same 60 instructions served by 1, 2 and 3 robots.

The office's instructions (the 30 base instructions of ``dataset/tasks.jsonl`` with everyone
available, twice, in a seeded order) are submitted to the Assistant -- the embedded
(symbolic) reasoner, the PPDR loop, the executors -- in the simulated office, with simulated
people answering and doing the hand-overs. The robots (``sim.fleet``) drive on the office
map along planned paths, each with its own locker, leased per robot, yielding to each other
through floor reservations (``nav.traffic``). Releases are seeded, one every ``--gap``
seconds on average, busier than one robot can keep up with. All in simulated time (a
virtual-time event loop: ``sim.virtual_time``), so robots, people and instructions overlap.

Per fleet size: instructions per hour (60 over the time from the first release to the last
end), the mean wait (release to the requester being told the outcome), outcomes, robot
contacts (two robots closer than a robot's width: collisions), deadlocks (a robot that waited
past its patience for another), the mean time robots yielded, and the instructions each
robot served. The speed-ups are over one robot.

Last stdout line: one JSON object. Run: python bench/fleet.py [--gap S] [--seed N] [--count N]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import logging
import statistics
import time
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np

from assistantx.agents.registry import reasoner_factory
from assistantx.core.office import PersonId, load_office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset import load_tasks
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.fleet import sim_fleet
from assistantx.sim.requester import Wish
from assistantx.sim.virtual_time import LoopClock, run_virtual

REPO = Path(__file__).resolve().parents[1]
ROBOT_WIDTH_M = 0.5


def instructions(count: int, gap_s: float, seed: int) -> list[tuple[float, Any]]:
    """(release time, task) for ``count`` instructions: the everyone-available tasks, cycled."""
    tasks = [t for t in load_tasks(REPO / "dataset" / "tasks.jsonl") if not t.unavailable]
    rng = np.random.default_rng(seed)
    chosen = [tasks[i % len(tasks)] for i in range(count)]
    order = rng.permutation(count)
    releases = np.cumsum(np.r_[0.0, rng.exponential(gap_s, count - 1)])
    return [(float(releases[k]), chosen[int(order[k])]) for k in range(count)]


async def serve(size: int, plan: list[tuple[float, Any]]) -> dict[str, Any]:
    office = load_office()
    clock = LoopClock()
    fleet = sim_fleet(office, clock, size)
    # Queueing for a robot is what is measured: no instruction is cut short by it (wall_s is
    # on the virtual clock here, so it would count simulated time too).
    limits = LoopLimits(deadline_s=24 * 3600.0, wall_s=None)
    assistant = fleet.assistant(reasoner_factory("symbolic", office, Settings()), limits=limits)
    released: dict[str, float] = {}
    async with fleet:
        await assistant.start()
        started = clock.now()
        try:
            for n, (release_s, task) in enumerate(plan):
                await asyncio.sleep(max(0.0, started + release_s - clock.now()))
                iid = f"i{n:02d}"
                fleet.wishes[iid] = Wish.from_goal(office, task.requester, task.goal)
                released[iid] = clock.now()
                await assistant.submit(
                    PersonId(task.requester), task.instruction, instruction_id=iid
                )
            ended = [await assistant.wait(iid) for iid in released]
        finally:
            await assistant.stop()
    ends = {s.instruction_id: float(s.trace.ended_at or clock.now()) for s in ended}
    span = max(ends.values()) - min(released.values())
    traffic = fleet.traffic
    yields = [w for _, w in traffic.waits]
    return {
        "instructions_per_hour": round(len(ended) / span * 3600, 1),
        "mean_wait_s": round(statistics.mean(ends[i] - released[i] for i in released), 1),
        "outcomes": dict(Counter(s.trace.outcome or "none" for s in ended)),
        "collisions": traffic.contacts,
        "closest_robots_m": None if size == 1 else round(traffic.separation_m, 2),
        "deadlocks": traffic.deadlocks,
        "mean_yield_s": round(statistics.mean(yields), 2) if yields else 0.0,
        "served_per_robot": [b.served for b in fleet.bodies],
        "driven_m": [round(b.robot.state().odometer_m, 1) for b in fleet.bodies],
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=60)
    parser.add_argument("--gap", type=float, default=60.0, help="mean seconds between releases")
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--sizes", default="1,2,3")
    args = parser.parse_args()
    logging.basicConfig(level=logging.WARNING)
    plan = instructions(args.count, args.gap, args.seed)
    results: dict[str, dict[str, Any]] = {}
    for size in (int(s) for s in args.sizes.split(",")):
        cpu = time.process_time()
        results[str(size)] = run_virtual(lambda size=size: serve(size, plan))  # type: ignore[misc]
        results[str(size)]["cpu_s"] = round(time.process_time() - cpu, 1)
        print(f"{size} robot(s): {results[str(size)]}", flush=True)
    summary: dict[str, Any] = {"fleet": results}
    if "1" in results:
        base = results["1"]["instructions_per_hour"]
        for size in ("2", "3"):
            if size in results:
                speedup = round(results[size]["instructions_per_hour"] / base, 2)
                summary[f"speedup_{size}_robots"] = speedup
    summary["deadlocks"] = sum(r["deadlocks"] for r in results.values())
    summary["collisions"] = sum(r["collisions"] for r in results.values())
    summary["two_robots_at_least_1_6x"] = summary.get("speedup_2_robots", 0.0) >= 1.6
    print(json.dumps(summary))


if __name__ == "__main__":
    main()
