"""Is the event loop free while the robot drives? ``GET /v1/robot`` latency, idle and while
driving on a real map, in one run.

Serves the app (uvicorn, in this process) with the navigator robot and AMCL on nav2's
warehouse map (``<repo>/maps/nav2``, or ``--map``), the office's locations anchored in
its reachable free space (placed, seeded). A client in its own thread reads ``GET
/v1/robot`` every ``--interval-s`` seconds: first ``--idle-s`` seconds with the robot idle,
then while the robot drives a tour of ``--legs`` legs between far-apart places (planning,
LiDAR, AMCL, obstacle layer and costmap run in a worker thread, the search in a worker
process). Reports p50/p99/max per
phase. Last stdout line: one JSON object.

Run: python bench/robot_service_latency.py [--map YAML] [--legs N] [--idle-s S]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path

import httpx
import numpy as np

from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.nav.anchor_check import place_anchors
from assistantx.nav.anchors import save_anchors
from assistantx.nav.costmap import Costmap
from assistantx.nav.occupancy_map import load_map
from assistantx.service.app import create_app
from assistantx.service.server import service_server

sys.path.insert(0, str(Path(__file__).resolve().parent))
from robot_real_maps import SHARED_MAPS

TOKEN = "bench-operator-token-000000001"


def _free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Reader(threading.Thread):
    """Reads GET /v1/robot at a steady rate; latencies (s) go into the current phase."""

    def __init__(self, url: str, interval_s: float) -> None:
        super().__init__(daemon=True)
        self.url, self.interval_s = url, interval_s
        self.phase = "idle"
        self.samples: dict[str, list[float]] = {"idle": [], "driving": []}
        self.moving_seen = 0
        self.stop = threading.Event()

    def run(self) -> None:
        headers = {"Authorization": f"Bearer {TOKEN}"}
        with httpx.Client(base_url=self.url, timeout=30, headers=headers) as client:
            while not self.stop.is_set():
                started = time.perf_counter()
                r = client.get("/v1/robot")
                elapsed = time.perf_counter() - started
                r.raise_for_status()
                if self.phase in self.samples:
                    self.samples[self.phase].append(elapsed)
                    self.moving_seen += self.phase == "driving" and bool(r.json()["moving"])
                time.sleep(max(0.0, self.interval_s - elapsed))


def _stats(values: list[float]) -> dict[str, float | int]:
    ms = sorted(v * 1000 for v in values)
    return {
        "n": len(ms),
        "p50_ms": round(statistics.median(ms), 2),
        "p99_ms": round(ms[min(len(ms) - 1, int(0.99 * len(ms)))], 2),
        "max_ms": round(ms[-1], 2),
    }


async def main_async(args: argparse.Namespace) -> dict[str, object]:
    office = load_office()
    grid = load_map(args.map)
    placed = place_anchors(Costmap.inflate(grid), len(office.locations), np.random.default_rng(3))
    ids = [loc.id for loc in office.locations]
    with tempfile.TemporaryDirectory() as tmp:
        anchors_yaml = Path(tmp) / "anchors.yaml"
        save_anchors(dict(zip(ids, placed.values(), strict=True)), anchors_yaml)
        settings = Settings(
            data_dir=Path(tmp) / "data",
            operator_token=TOKEN,
            map=args.map,
            map_anchors=anchors_yaml,
            speedup=args.speedup,
        )
        app = create_app(settings)
        port = _free_port()
        server = service_server(app, "127.0.0.1", port, log_level="warning")
        serving = asyncio.create_task(server.serve())
        for _ in range(600):  # uvicorn offers no event for "listening"
            if server.started:
                break
            await asyncio.sleep(0.05)
        runtime = app.state.runtime
        robot = runtime.sim.robot
        reader = Reader(f"http://127.0.0.1:{port}", args.interval_s)
        reader.start()
        await asyncio.sleep(args.idle_s)
        # A tour between far-apart places: each next stop is the farthest from here.
        anchor = dict(zip(ids, placed.values(), strict=True))
        here = robot.state().place
        stops = []
        for _ in range(args.legs):
            a = anchor[here]
            here = max(ids, key=lambda i: np.hypot(anchor[i].x - a.x, anchor[i].y - a.y))
            stops.append(here)
        reader.phase = "driving"
        started = time.perf_counter()
        driven = 0.0
        for stop in stops:
            result = await robot.move_to(stop)
            driven += result.distance_m
        drive_s = time.perf_counter() - started
        reader.phase = "done"
        reader.stop.set()
        reader.join()
        server.should_exit = True
        await serving
    idle, driving = _stats(reader.samples["idle"]), _stats(reader.samples["driving"])
    return {
        "map": args.map.stem,
        "idle": idle,
        "driving": driving,
        "driving_reads_while_moving": reader.moving_seen,
        "legs": args.legs,
        "driven_m": round(driven, 1),
        "drive_wall_s": round(drive_s, 1),
        "speedup": args.speedup,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", type=Path, default=SHARED_MAPS / "warehouse.yaml")
    parser.add_argument("--legs", type=int, default=2)
    parser.add_argument("--idle-s", type=float, default=10.0)
    parser.add_argument("--interval-s", type=float, default=0.05)
    parser.add_argument("--speedup", type=float, default=10.0)
    args = parser.parse_args()
    result = asyncio.run(main_async(args))
    idle, driving = result["idle"], result["driving"]
    assert isinstance(idle, dict)
    assert isinstance(driving, dict)
    print(
        f"GET /v1/robot on {result['map']}: idle p50 {idle['p50_ms']} ms p99 {idle['p99_ms']} "
        f"ms (n {idle['n']}); driving p50 {driving['p50_ms']} ms p99 {driving['p99_ms']} ms "
        f"max {driving['max_ms']} ms (n {driving['n']}, {result['driven_m']} m)"
    )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
