"""Load on the running service: N instructions submitted concurrently over REST.

Starts ``python -m assistantx serve`` on a free port with a fresh data directory (simulated
travel and replies sped up), follows ``GET /v1/events`` (SSE), submits N instructions at once
and reports the REST calls' and the whole instructions' latencies. The robot is one body, so
instructions queue for it; whole-instruction latency includes that queue.

    python bench/service_load.py [--n 200] [--speedup 1000]

Uses the embedded reasoner (``assistantx.symbolic``) when it is installed, else the tests'
deterministic stapler reasoner (said in the output). Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import asyncio
import importlib.util
import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import httpx

ROOT = Path(__file__).resolve().parents[1]
TOKEN = "bench-operator-token-000000001"
REQUESTERS = ["lee", "mao", "sun", "dang", "zhou", "chen", "yang", "lin", "xu", "zheng"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _pct(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def _start(data_dir: Path, port: int, speedup: float) -> tuple[subprocess.Popen[bytes], str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(
        ASSISTANTX_DATA_DIR=str(data_dir),
        ASSISTANTX_OPERATOR_TOKEN=TOKEN,
        ASSISTANTX_SPEEDUP=str(speedup),
        ASSISTANTX_MAX_BODY_BYTES="65536",
    )
    reasoner = "symbolic (embedded)"
    has_symbolic = importlib.util.find_spec("assistantx.symbolic") is not None
    if not has_symbolic or not hasattr(
        importlib.import_module("assistantx.symbolic"), "build_factory"
    ):
        env["ASSISTANTX_REASONER_BUILDER"] = "service.stapler_reasoner:build_factory"
        env["PYTHONPATH"] = str(ROOT / "tests")
        reasoner = "stapler (tests' stand-in; assistantx.symbolic.build_factory not found)"
    log = (data_dir.parent / "server.log").open("wb")
    cmd = [sys.executable, "-m", "assistantx", "serve", "--host", "127.0.0.1", "--port", str(port)]
    process = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT)
    return process, reasoner


async def _wait_ready(url: str) -> None:
    async with httpx.AsyncClient() as client:
        for _ in range(300):
            try:
                if (await client.get(f"{url}/readyz")).status_code == 200:
                    return
            except httpx.TransportError:
                pass
            await asyncio.sleep(0.1)
    raise RuntimeError("server did not become ready")


async def _follow(
    url: str, ended: dict[str, float], outcomes: dict[str, str], n: int, done: asyncio.Event
) -> None:
    last = 0
    async with httpx.AsyncClient(timeout=None) as client:
        while True:  # a listener that falls behind is dropped: reconnect with Last-Event-ID
            headers = {"Authorization": f"Bearer {TOKEN}", "Last-Event-ID": str(last)}
            async with client.stream("GET", f"{url}/v1/events", headers=headers) as response:
                async for line in response.aiter_lines():
                    if line.startswith("id: "):
                        last = int(line[4:])
                    if not line.startswith("data: "):
                        continue
                    event = json.loads(line[6:])
                    if event["kind"] == "instruction_ended":
                        ended[event["instruction_id"]] = time.perf_counter()
                        outcomes[event["instruction_id"]] = str(event["data"].get("outcome"))
                        if len(ended) >= n:
                            done.set()


async def _run(url: str, n: int) -> dict[str, object]:
    ended: dict[str, float] = {}
    outcomes: dict[str, str] = {}
    all_ended = asyncio.Event()
    follower = asyncio.create_task(_follow(url, ended, outcomes, n, all_ended))
    await asyncio.sleep(0.3)
    limits = httpx.Limits(max_connections=n, max_keepalive_connections=n)
    headers = {"Authorization": f"Bearer {TOKEN}"}
    submitted: dict[str, float] = {}
    rest: list[float] = []
    async with httpx.AsyncClient(base_url=url, limits=limits, timeout=60) as client:

        async def submit(i: int) -> None:
            body = {"requester": REQUESTERS[i % len(REQUESTERS)], "text": "bring me a stapler"}
            t0 = time.perf_counter()
            r = await client.post("/v1/instructions", json=body, headers=headers)
            rest.append(time.perf_counter() - t0)
            r.raise_for_status()
            submitted[r.json()["id"]] = t0

        t_start = time.perf_counter()
        await asyncio.gather(*(submit(i) for i in range(n)))
        t_submitted = time.perf_counter()
        await all_ended.wait()  # the data dir is fresh: every ended event is one of ours
        t_done = time.perf_counter()
        gets: list[float] = []
        for iid in list(submitted)[:50]:
            t0 = time.perf_counter()
            (await client.get(f"/v1/instructions/{iid}", headers=headers)).raise_for_status()
            gets.append(time.perf_counter() - t0)
    follower.cancel()
    whole = [ended[i] - t0 for i, t0 in submitted.items()]
    return {
        "n": n,
        "submit_wall_s": round(t_submitted - t_start, 3),
        "submit_throughput_per_s": round(n / (t_submitted - t_start), 1),
        "post_p50_ms": round(1000 * _pct(rest, 0.5), 1),
        "post_p99_ms": round(1000 * _pct(rest, 0.99), 1),
        "get_p50_ms": round(1000 * _pct(gets, 0.5), 1),
        "get_p99_ms": round(1000 * _pct(gets, 0.99), 1),
        "instruction_p50_s": round(_pct(whole, 0.5), 2),
        "instruction_p99_s": round(_pct(whole, 0.99), 2),
        "instruction_mean_s": round(statistics.mean(whole), 2),
        "completed_per_s": round(n / (t_done - t_start), 2),
        "outcomes": {k: list(outcomes.values()).count(k) for k in sorted(set(outcomes.values()))},
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--speedup", type=float, default=1000.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        port = _free_port()
        process, reasoner = _start(Path(tmp) / "data", port, args.speedup)
        url = f"http://127.0.0.1:{port}"
        try:
            asyncio.run(_wait_ready(url))
            figures = asyncio.run(_run(url, args.n))
        finally:
            process.terminate()
            process.wait(15)
    figures.update(reasoner=reasoner, speedup=args.speedup)
    print(f"reasoner: {reasoner}; simulated time x{args.speedup:g}")
    print(
        f"submitted {args.n} instructions in {figures['submit_wall_s']} s "
        f"({figures['submit_throughput_per_s']}/s); POST p50 {figures['post_p50_ms']} ms, "
        f"p99 {figures['post_p99_ms']} ms; GET p50 {figures['get_p50_ms']} ms"
    )
    print(
        f"whole instructions: p50 {figures['instruction_p50_s']} s, p99 "
        f"{figures['instruction_p99_s']} s ({figures['completed_per_s']}/s; outcomes "
        f"{figures['outcomes']})"
    )
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
