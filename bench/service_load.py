"""Load on the running service: N instructions of every kind submitted concurrently over REST.

Starts ``python -m assistantx serve`` on a free port with a fresh data directory (simulated
travel and replies sped up, everyone available), follows ``GET /v1/events`` (SSE), submits N
instructions at once — the 30 base instructions of ``dataset/base_instructions.yaml`` in turn,
each from its own requester — and, while they run, reads an instruction, the list and the
robot every 50 ms. Reports throughput, p50/p99 of the REST calls and of whole instructions,
and the outcomes per kind. The robot is one body, so instructions queue for it;
whole-instruction latency includes that queue.

    python bench/service_load.py [--n 200] [--speedup 1000] [--robot navigator|sim]
        [--localize | --no-localize]

Uses the embedded reasoner (``assistantx.symbolic``) when it is installed, else the tests'
deterministic stapler reasoner (said in the output). Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import asyncio
import importlib.util
import json
import os
import random
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
BASES = ROOT / "dataset" / "base_instructions.yaml"


def _instructions() -> list[tuple[str, str, str]]:
    """(requester, text, kind) of every base instruction, in file order."""
    import yaml

    bases = yaml.safe_load(BASES.read_text())["instructions"]
    return [(b["requester"], b["text"], "+".join(p["kind"] for p in b["parts"])) for b in bases]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _pct(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def _start(
    data_dir: Path, port: int, args: argparse.Namespace
) -> tuple[subprocess.Popen[bytes], str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(
        ASSISTANTX_DATA_DIR=str(data_dir),
        ASSISTANTX_OPERATOR_TOKEN=TOKEN,
        ASSISTANTX_SPEEDUP=str(args.speedup),
        ASSISTANTX_MAX_BODY_BYTES="65536",
        ASSISTANTX_ROBOT=args.robot,
        ASSISTANTX_ROBOT_LOCALIZE=str(args.localize).lower(),
        # The queue for the one robot counts as simulated time: x1000, the default hour
        # would end queued instructions after 3.6 real seconds.
        ASSISTANTX_INSTRUCTION_DEADLINE_S=str(args.deadline_s),
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


async def _probe(
    client: httpx.AsyncClient,
    submitted: dict[str, float],
    samples: dict[str, list[tuple[float, float]]],
    stop: asyncio.Event,
) -> None:
    """Reads while the load runs: (time sent, seconds taken) per route."""
    headers = {"Authorization": f"Bearer {TOKEN}"}
    paths = {
        "get_instruction": lambda: f"/v1/instructions/{random.choice(list(submitted))}",
        "list_instructions": lambda: "/v1/instructions?limit=50",
        "robot": lambda: "/v1/robot",
    }
    while not stop.is_set():
        for name, path in paths.items():
            if name == "get_instruction" and not submitted:
                continue
            t0 = time.perf_counter()
            (await client.get(path(), headers=headers)).raise_for_status()
            samples[name].append((t0, time.perf_counter() - t0))
        await asyncio.sleep(0.05)


async def _run(url: str, n: int) -> dict[str, object]:
    ended: dict[str, float] = {}
    outcomes: dict[str, str] = {}
    all_ended = asyncio.Event()
    follower = asyncio.create_task(_follow(url, ended, outcomes, n, all_ended))
    await asyncio.sleep(0.3)
    limits = httpx.Limits(max_connections=n + 4, max_keepalive_connections=n + 4)
    headers = {"Authorization": f"Bearer {TOKEN}"}
    submitted: dict[str, float] = {}
    kinds: dict[str, str] = {}
    posts: list[float] = []
    samples: dict[str, list[tuple[float, float]]] = {
        "get_instruction": [],
        "list_instructions": [],
        "robot": [],
    }
    mix = _instructions()
    async with httpx.AsyncClient(base_url=url, limits=limits, timeout=120) as client:

        async def submit(i: int) -> None:
            requester, text, kind = mix[i % len(mix)]
            t0 = time.perf_counter()
            r = await client.post(
                "/v1/instructions", json={"requester": requester, "text": text}, headers=headers
            )
            posts.append(time.perf_counter() - t0)
            r.raise_for_status()
            submitted[r.json()["id"]] = t0
            kinds[r.json()["id"]] = kind

        stop_probe = asyncio.Event()
        probe = asyncio.create_task(_probe(client, submitted, samples, stop_probe))
        t_start = time.perf_counter()
        await asyncio.gather(*(submit(i) for i in range(n)))
        t_submitted = time.perf_counter()
        await all_ended.wait()  # the data dir is fresh: every ended event is one of ours
        t_done = time.perf_counter()
        stop_probe.set()
        await probe
        after: list[float] = []  # every instruction read once the load is over
        largest = 0
        for iid in submitted:
            t0 = time.perf_counter()
            r = await client.get(f"/v1/instructions/{iid}", headers=headers)
            after.append(time.perf_counter() - t0)
            largest = max(largest, len(r.content))
    follower.cancel()
    whole = [ended[i] - t0 for i, t0 in submitted.items()]
    per_kind: dict[str, dict[str, int]] = {}
    for iid, kind in kinds.items():
        tally = per_kind.setdefault(kind, {})
        tally[outcomes[iid]] = tally.get(outcomes[iid], 0) + 1
    extra = sorted(set(ended) - set(submitted))
    figures: dict[str, object] = {
        "n": n,
        "submit_wall_s": round(t_submitted - t_start, 3),
        "submit_throughput_per_s": round(n / (t_submitted - t_start), 1),
        "post_p50_ms": round(1000 * _pct(posts, 0.5), 1),
        "post_p99_ms": round(1000 * _pct(posts, 0.99), 1),
    }
    for name, timed in samples.items():
        took = [seconds for _, seconds in timed]
        figures[f"{name}_n"] = len(took)
        figures[f"{name}_p50_ms"] = round(1000 * _pct(took, 0.5), 1)
        figures[f"{name}_p99_ms"] = round(1000 * _pct(took, 0.99), 1)
        figures[f"{name}_max_ms"] = round(1000 * max(took), 1)
    figures.update(
        get_after_p50_ms=round(1000 * _pct(after, 0.5), 1),
        get_after_p99_ms=round(1000 * _pct(after, 0.99), 1),
        largest_instruction_kb=round(largest / 1024, 1),
        instruction_p50_s=round(_pct(whole, 0.5), 2),
        instruction_p99_s=round(_pct(whole, 0.99), 2),
        instruction_mean_s=round(statistics.mean(whole), 2),
        wall_s=round(t_done - t_start, 1),
        completed_per_s=round(n / (t_done - t_start), 2),
        outcomes={
            k: [outcomes[i] for i in submitted].count(k)
            for k in sorted({outcomes[i] for i in submitted})
        },
        outcomes_by_kind=per_kind,
        unsubmitted_instructions=len(extra),  # started by a simulated person's unprompted DM
    )
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--speedup", type=float, default=1000.0)
    parser.add_argument("--robot", choices=["navigator", "sim"], default="navigator")
    parser.add_argument("--localize", action=argparse.BooleanOptionalAction, default=False)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--deadline-s", type=float, default=30 * 24 * 3600.0, help="simulated")
    args = parser.parse_args()
    random.seed(args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        port = _free_port()
        process, reasoner = _start(Path(tmp) / "data", port, args)
        url = f"http://127.0.0.1:{port}"
        try:
            asyncio.run(_wait_ready(url))
            figures = asyncio.run(_run(url, args.n))
        finally:
            process.terminate()
            process.wait(15)
    robot = f"{args.robot}{' + AMCL' if args.robot == 'navigator' and args.localize else ''}"
    figures.update(reasoner=reasoner, speedup=args.speedup, robot=robot)
    print(f"reasoner: {reasoner}; robot: {robot}; simulated time x{args.speedup:g}")
    print(
        f"submitted {args.n} instructions in {figures['submit_wall_s']} s "
        f"({figures['submit_throughput_per_s']}/s); POST p50 {figures['post_p50_ms']} ms, "
        f"p99 {figures['post_p99_ms']} ms"
    )
    for name in ("get_instruction", "list_instructions", "robot"):
        print(
            f"during the load, {name}: p50 {figures[f'{name}_p50_ms']} ms, p99 "
            f"{figures[f'{name}_p99_ms']} ms, max {figures[f'{name}_max_ms']} ms "
            f"({figures[f'{name}_n']} calls)"
        )
    print(
        f"after the load, get_instruction: p50 {figures['get_after_p50_ms']} ms, p99 "
        f"{figures['get_after_p99_ms']} ms (largest body {figures['largest_instruction_kb']} KiB)"
    )
    print(
        f"whole instructions: p50 {figures['instruction_p50_s']} s, p99 "
        f"{figures['instruction_p99_s']} s; all done in {figures['wall_s']} s "
        f"({figures['completed_per_s']}/s); outcomes {figures['outcomes']}; "
        f"{figures['unsubmitted_instructions']} started by unprompted messages"
    )
    for kind, tally in sorted(figures["outcomes_by_kind"].items()):  # type: ignore[attr-defined]
        print(f"  {kind}: {tally}")
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
