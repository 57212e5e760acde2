"""Load on the running service: N instructions of every kind submitted concurrently over REST.

Starts ``python -m assistantx serve`` on a free port with a fresh data directory (simulated
travel and replies sped up, everyone available), follows ``GET /v1/events`` (SSE). First, idle:
a few POSTs and GETs one at a time. Then a burst: N instructions submitted at once — the 30 base
instructions of ``dataset/base_instructions.yaml`` in turn, each from its own requester; by
default over N connections opened beforehand, each POST prepared as bytes (``_raw_http``:
httpx's own CPU for the burst was as much as the service's, on the same cores; ``--burst-client
httpx`` sends it as before) — and, for a fixed load phase (``--load-s``), an instruction, the
list and the robot are read every 50 ms and one more instruction is POSTed every 250 ms (POST
latency with N running). Then a bounded drain (``--drain-s``): what has not ended by then is
cancelled over REST and counted, so the bench ends in load + drain + set-up whatever the machine
(an open-ended "until every instruction ends" ran for over 11 minutes at N=200 on the 2-core
machine, since POSTs kept adding work for the one robot). Reports p50/p99 idle, in the burst and
under load, throughput, whole instructions and the outcomes per kind, and the service's loop-lag
gauge, sampled every second during the load (its maximum is the longest stall of the loop), and
the service's CPU per call and per trace event (those the follower received) in the burst and
the load; writes ``service_load.png`` (``--out``). The robot is one body, so instructions queue
for it; whole-instruction latency includes that.

    python bench/service_load.py [--n 200] [--load-s 60] [--drain-s 90] [--speedup 1000]
        [--robot navigator|sim] [--localize | --no-localize] [--burst-client raw|httpx]
        [--out DIR]

Uses the embedded reasoner (``assistantx.agents.symbolic``) when it is installed, else the tests'
deterministic stapler reasoner (said in the output). Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
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
from collections.abc import Awaitable, Callable
from pathlib import Path

import httpx
from _raw_http import RawConnections

ROOT = Path(__file__).resolve().parents[1]
IDLE_CALLS = 30
IDLE_WAIT_S = 240.0  # the idle instructions, one robot, on a loaded 2-core machine
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


class _CpuMeter:
    """The service's CPU time (all threads) and its loop thread's time on a CPU and waiting
    for one (Linux ``/proc``): on a shared machine a slow answer is often the loop waiting
    for a core, not working; these tell the two apart. Empty figures where ``/proc`` is not."""

    def __init__(self, pid: int) -> None:
        self.pid = pid

    def read(self) -> tuple[float, float, float] | None:
        """(process CPU s, loop thread on-CPU s, loop thread run-queue wait s)."""
        try:
            stat = Path(f"/proc/{self.pid}/stat").read_text().rsplit(")", 1)[1].split()
            sched = Path(f"/proc/{self.pid}/task/{self.pid}/schedstat").read_text().split()
        except OSError:
            return None
        ticks = os.sysconf("SC_CLK_TCK")
        return (int(stat[11]) + int(stat[12])) / ticks, int(sched[0]) / 1e9, int(sched[1]) / 1e9

    @staticmethod
    def phase(
        name: str,
        before: tuple[float, float, float] | None,
        after: object,
        calls: int,
        events: int,
    ) -> dict[str, object]:
        if before is None or not isinstance(after, tuple):
            return {}
        cpu, on_cpu, waiting = (a - b for a, b in zip(after, before, strict=True))
        return {
            f"{name}_service_cpu_s": round(cpu, 2),
            f"{name}_service_cpu_ms_per_call": round(1000 * cpu / max(calls, 1), 2),
            f"{name}_events": events,  # journaled trace events the follower received
            f"{name}_service_cpu_ms_per_event": round(1000 * cpu / events, 2) if events else None,
            f"{name}_loop_thread_on_cpu_s": round(on_cpu, 2),
            f"{name}_loop_thread_runqueue_wait_s": round(waiting, 2),
            f"{name}_load_avg_1min": round(os.getloadavg()[0], 2),
        }


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
        # A load test sends each requester far more than a person's per-minute bound.
        ASSISTANTX_INSTRUCTIONS_PER_MINUTE="0",
    )
    reasoner = "symbolic (embedded)"
    has_symbolic = importlib.util.find_spec("assistantx.agents.symbolic") is not None
    if not has_symbolic or not hasattr(
        importlib.import_module("assistantx.agents.symbolic"), "build_factory"
    ):
        env["ASSISTANTX_REASONER_BUILDER"] = "service.stapler_reasoner:build_factory"
        env["PYTHONPATH"] = str(ROOT / "tests")
        reasoner = "stapler (tests' stand-in; assistantx.agents.symbolic.build_factory not found)"
    log = (args.out / "service_load-server.log").open("wb")  # kept: read it when a run fails
    cmd = [sys.executable, "-m", "assistantx", "serve", "--host", "127.0.0.1", "--port", str(port)]
    process = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT)
    return process, reasoner


async def _wait_ready(url: str) -> None:
    async with httpx.AsyncClient() as client:
        for _ in range(1200):  # two minutes: a shared machine starts it slowly
            try:
                if (await client.get(f"{url}/readyz")).status_code == 200:
                    return
            except httpx.TransportError:
                pass
            await asyncio.sleep(0.1)
    raise RuntimeError("server did not become ready")


async def _follow(
    url: str, ended: dict[str, float], outcomes: dict[str, str], seen: list[int]
) -> None:
    """Follows every event; ``seen[0]``: how many so far (the service's CPU per event)."""
    last = 0
    async with httpx.AsyncClient(timeout=None) as client:
        while True:  # a listener that falls behind is dropped: reconnect with Last-Event-ID
            headers = {"Authorization": f"Bearer {TOKEN}", "Last-Event-ID": str(last)}
            path = f"{url}/v1/events?replay=10000"  # the bench must see every ended event
            async with client.stream("GET", path, headers=headers) as response:
                async for line in response.aiter_lines():
                    if line.startswith("id: "):
                        last = int(line[4:])
                    if not line.startswith("data: "):
                        continue
                    event = json.loads(line[6:])
                    seen[0] += 1
                    if event["kind"] == "instruction_ended":
                        ended[event["instruction_id"]] = time.perf_counter()
                        outcomes[event["instruction_id"]] = str(event["data"].get("outcome"))


GET_PATHS = {
    "get_instruction": lambda ids: f"/v1/instructions/{random.choice(ids)}",
    "list_instructions": lambda ids: "/v1/instructions?limit=50",
    "robot": lambda ids: "/v1/robot",
}


async def _probe(
    client: httpx.AsyncClient,
    submitted: dict[str, float],
    samples: dict[str, list[tuple[float, float]]],
    stop: asyncio.Event,
) -> None:
    """Reads while the load runs: (time sent, seconds taken) per route."""
    headers = {"Authorization": f"Bearer {TOKEN}"}
    while not stop.is_set():
        for name, path in GET_PATHS.items():
            if name == "get_instruction" and not submitted:
                continue
            t0 = time.perf_counter()
            (await client.get(path(list(submitted)), headers=headers)).raise_for_status()
            samples[name].append((t0, time.perf_counter() - t0))
        await asyncio.sleep(0.05)


async def _post_under_load(
    submit: Callable[[int], Awaitable[float]], during: list[float], stop: asyncio.Event
) -> None:
    """One more instruction every 250 ms while the others run."""
    i = 0
    while not stop.is_set():
        during.append(await submit(10_000 + i))
        i += 1
        await asyncio.sleep(0.25)


LAG = "assistantx_event_loop_lag_max_seconds"
OWN_LAG = "assistantx_event_loop_own_lag_max_seconds"  # less the loop's waits for a CPU


async def _loop_lags(client: httpx.AsyncClient) -> dict[str, float]:
    """The service's loop-lag gauges (the longest stall of the last minute)."""
    text = (await client.get("/metrics", headers={"Authorization": f"Bearer {TOKEN}"})).text
    found: dict[str, float] = {}
    for line in text.splitlines():
        name, _, value = line.partition(" ")
        if name in (LAG, OWN_LAG):
            found[name] = float(value)
    return found


async def _watch_lag(
    client: httpx.AsyncClient, lags: list[dict[str, float]], stop: asyncio.Event
) -> None:
    """The service's loop-lag gauges once a second while the load runs."""
    while not stop.is_set():
        lags.append(await _loop_lags(client))
        await asyncio.sleep(1.0)


async def _ended_within(submitted: dict[str, float], ended: dict[str, float], s: float) -> bool:
    """Whether every submitted instruction has ended within ``s`` seconds from now."""
    deadline = time.perf_counter() + s
    while not set(submitted) <= set(ended):  # the follower fills ``ended``
        if time.perf_counter() > deadline:
            return False
        await asyncio.sleep(0.1)
    return True


async def _run(
    url: str, n: int, load_s: float, drain_s: float, meter: _CpuMeter, burst_client: str
) -> dict[str, object]:
    ended: dict[str, float] = {}
    outcomes: dict[str, str] = {}
    seen = [0]
    follower = asyncio.create_task(_follow(url, ended, outcomes, seen))
    await asyncio.sleep(0.3)
    # Pooled connections are dropped before uvicorn's 5 s keep-alive closes them: one reused
    # just as the server closed it failed the burst with a ReadError.
    limits = httpx.Limits(
        max_connections=n + 4, max_keepalive_connections=n + 4, keepalive_expiry=3.0
    )
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

        async def submit(i: int) -> float:
            requester, text, kind = mix[i % len(mix)]
            t0 = time.perf_counter()
            r = await client.post(
                "/v1/instructions", json={"requester": requester, "text": text}, headers=headers
            )
            took = time.perf_counter() - t0
            r.raise_for_status()
            submitted[r.json()["id"]] = t0
            kinds[r.json()["id"]] = kind
            return took

        # Idle: one call at a time, nothing running.
        idle_posts = [await submit(5_000 + i) for i in range(IDLE_CALLS // 2)]
        if not await _ended_within(submitted, ended, IDLE_WAIT_S):
            raise RuntimeError(f"the idle instructions did not end within {IDLE_WAIT_S:g} s")
        idle_gets: list[float] = []
        for i in range(IDLE_CALLS):
            path = list(GET_PATHS.values())[i % len(GET_PATHS)](list(submitted))
            t0 = time.perf_counter()
            (await client.get(path, headers=headers)).raise_for_status()
            idle_gets.append(time.perf_counter() - t0)
        lag_idle = await _loop_lags(client)

        stop_probe = asyncio.Event()
        lags: list[dict[str, float]] = []
        probe = asyncio.create_task(_probe(client, submitted, samples, stop_probe))
        watch = asyncio.create_task(_watch_lag(client, lags, stop_probe))
        async with contextlib.AsyncExitStack() as burst_stack:
            if burst_client == "raw":  # connected before the burst, requests prepared
                host, _, port = url.removeprefix("http://").partition(":")
                raw = RawConnections(host, int(port), n)
                await burst_stack.enter_async_context(raw)
                burst = [mix[i % len(mix)] for i in range(n)]
                prepared = [
                    raw.request("/v1/instructions", {"requester": r, "text": t}, TOKEN)
                    for r, t, _ in burst
                ]
            t_start = time.perf_counter()
            cpu_burst, seen_burst = meter.read(), seen[0]
            client_burst = time.process_time()
            if burst_client == "raw":
                answers = await raw.post_all(prepared)
            else:
                posts += await asyncio.gather(*(submit(i) for i in range(n)))
            t_submitted = time.perf_counter()
            cpu_load, seen_load = meter.read(), seen[0]
            client_cpu_burst_s = time.process_time() - client_burst
        if burst_client == "raw":
            for (took, status, answer), (_, _, kind) in zip(answers, burst, strict=True):
                if status != 202:
                    raise RuntimeError(f"a burst POST was answered {status}: {answer[:200]!r}")
                iid = json.loads(answer)["id"]
                submitted[iid], kinds[iid] = t_start, kind
                posts.append(took)
        during: list[float] = []
        poster = asyncio.create_task(_post_under_load(submit, during, stop_probe))
        await asyncio.sleep(load_s)  # the fixed load phase: the probes and POSTs run meanwhile
        stop_probe.set()
        await asyncio.gather(probe, poster, watch)
        cpu_end, seen_end = meter.read(), seen[0]
        drained = await _ended_within(submitted, ended, drain_s)
        t_done = time.perf_counter()
        unfinished = sorted(set(submitted) - set(ended))
        for iid in unfinished:  # the bounded end: what is left is cancelled, and counted
            await client.post(f"/v1/instructions/{iid}/cancel", headers=headers)
        await _ended_within(submitted, ended, 30)
        lags.append(await _loop_lags(client))
        after: list[float] = []  # every instruction read once the load is over
        largest = 0
        for iid in submitted:
            t0 = time.perf_counter()
            r = await client.get(f"/v1/instructions/{iid}", headers=headers)
            after.append(time.perf_counter() - t0)
            largest = max(largest, len(r.content))
    follower.cancel()
    whole = [ended[i] - t0 for i, t0 in submitted.items() if i in ended and i not in unfinished]
    gets_during = [t for timed in samples.values() for _, t in timed]
    per_kind: dict[str, dict[str, int]] = {}
    for iid, kind in kinds.items():
        tally = per_kind.setdefault(kind, {})
        outcome = outcomes.get(iid, "not ended")
        tally[outcome] = tally.get(outcome, 0) + 1
    extra = sorted(set(ended) - set(submitted))
    figures: dict[str, object] = {
        "n": n,
        "submit_wall_s": round(t_submitted - t_start, 3),
        "submit_throughput_per_s": round(n / (t_submitted - t_start), 1),
        "post_p50_ms": round(1000 * _pct(posts, 0.5), 1),
        "post_p99_ms": round(1000 * _pct(posts, 0.99), 1),
        "idle_post_p50_ms": round(1000 * _pct(idle_posts, 0.5), 1),
        "idle_post_p99_ms": round(1000 * _pct(idle_posts, 0.99), 1),
        "idle_get_p50_ms": round(1000 * _pct(idle_gets, 0.5), 1),
        "idle_get_p99_ms": round(1000 * _pct(idle_gets, 0.99), 1),
        "loaded_post_n": len(during),
        "loaded_post_p50_ms": round(1000 * _pct(during, 0.5), 1),
        "loaded_post_p99_ms": round(1000 * _pct(during, 0.99), 1),
        "loaded_get_p50_ms": round(1000 * _pct(gets_during, 0.5), 1),
        "loaded_get_p99_ms": round(1000 * _pct(gets_during, 0.99), 1),
        "loop_lag_max_s_idle": lag_idle.get(LAG),
        "loop_lag_max_s_loaded": max((lag[LAG] for lag in lags if LAG in lag), default=None),
        "loop_own_lag_max_s_idle": lag_idle.get(OWN_LAG),  # None: a service without it
        "loop_own_lag_max_s_loaded": max(
            (lag[OWN_LAG] for lag in lags if OWN_LAG in lag), default=None
        ),
        # This process's own CPU in the burst: on a 2-core machine the client's 200 concurrent
        # httpx requests compete with the service for the cores, and the burst's POST
        # latencies include the time the client took to send them and read their answers.
        "burst_client_cpu_s": round(client_cpu_burst_s, 2),
        "burst_client": burst_client,
        "load_s": load_s,
        "drained": drained,
        "cancelled_after_drain": len(unfinished),
    }
    figures |= _CpuMeter.phase("burst", cpu_burst, cpu_load, n, seen_load - seen_burst)
    load_calls = len(during) + sum(len(timed) for timed in samples.values())
    figures |= _CpuMeter.phase("load", cpu_load, cpu_end, load_calls, seen_end - seen_load)
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
        completed_per_s=round(len(set(ended) & set(submitted)) / (t_done - t_start), 2),
        outcomes={
            k: [outcomes.get(i, "not ended") for i in submitted].count(k)
            for k in sorted({outcomes.get(i, "not ended") for i in submitted})
        },
        outcomes_by_kind=per_kind,
        instructions_total=len(submitted),
        unsubmitted_instructions=len(extra),  # started by a simulated person's unprompted DM
    )
    return figures


def _plot(figures: dict[str, object], out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    phases = [
        ("idle", "idle_post", "idle_get"),
        (f"burst of {figures['n']}", "post", None),
        (f"{figures['n']} running", "loaded_post", "loaded_get"),
    ]
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    for ax, q in zip(axes, ("p50", "p99"), strict=True):
        labels = [p[0] for p in phases]
        posts = [float(figures[f"{p[1]}_{q}_ms"]) for p in phases]  # type: ignore[arg-type]
        gets = [float(figures[f"{p[2]}_{q}_ms"]) if p[2] else 0.0 for p in phases]  # type: ignore[arg-type]
        xs = range(len(phases))
        ax.bar([x - 0.2 for x in xs], posts, width=0.4, label="POST /v1/instructions")
        ax.bar([x + 0.2 for x in xs], gets, width=0.4, label="GET (instruction, list, robot)")
        ax.set_xticks(list(xs), labels)
        ax.set_ylabel("ms")
        ax.set_title(f"{q} latency", fontsize=10)
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = out / "service_load.png"
    fig.savefig(path, dpi=100)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--load-s", type=float, default=60.0, help="the load phase (real s)")
    parser.add_argument(
        "--drain-s", type=float, default=90.0, help="then the wait for the rest (real s)"
    )
    parser.add_argument("--speedup", type=float, default=1000.0)
    parser.add_argument("--robot", choices=["navigator", "sim"], default="navigator")
    parser.add_argument("--localize", action=argparse.BooleanOptionalAction, default=False)
    parser.add_argument(
        "--burst-client",
        choices=["raw", "httpx"],
        default="raw",
        help="the burst's client: raw (connected beforehand, prepared requests; measures the"
        " service) or httpx (as the other phases; its own CPU is as much as the service's)",
    )
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--deadline-s", type=float, default=30 * 24 * 3600.0, help="simulated")
    parser.add_argument("--out", type=Path, default=Path("results/bench"))
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    random.seed(args.seed)
    began = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        port = _free_port()
        process, reasoner = _start(Path(tmp) / "data", port, args)
        url = f"http://127.0.0.1:{port}"
        try:
            asyncio.run(_wait_ready(url))
            meter = _CpuMeter(process.pid)
            figures = asyncio.run(
                _run(url, args.n, args.load_s, args.drain_s, meter, args.burst_client)
            )
        finally:
            process.terminate()
            process.wait(15)
    robot = f"{args.robot}{' + AMCL' if args.robot == 'navigator' and args.localize else ''}"
    figures.update(
        reasoner=reasoner,
        speedup=args.speedup,
        robot=robot,
        bench_wall_s=round(time.perf_counter() - began, 1),
    )
    figures["plot"] = str(_plot(figures, args.out))
    print(f"reasoner: {reasoner}; robot: {robot}; simulated time x{args.speedup:g}")
    print(
        f"submitted {args.n} instructions ({args.burst_client} client) in "
        f"{figures['submit_wall_s']} s "
        f"({figures['submit_throughput_per_s']}/s); POST p50 {figures['post_p50_ms']} ms, "
        f"p99 {figures['post_p99_ms']} ms"
    )
    print(
        f"idle: POST p50 {figures['idle_post_p50_ms']} ms, p99 {figures['idle_post_p99_ms']} ms;"
        f" GET p50 {figures['idle_get_p50_ms']} ms, p99 {figures['idle_get_p99_ms']} ms"
    )
    print(
        f"with {args.n} running: POST p50 {figures['loaded_post_p50_ms']} ms, p99 "
        f"{figures['loaded_post_p99_ms']} ms ({figures['loaded_post_n']} calls); GET p50 "
        f"{figures['loaded_get_p50_ms']} ms, p99 {figures['loaded_get_p99_ms']} ms; longest "
        f"loop stall {figures['loop_lag_max_s_loaded']} s, longest less its waits for a CPU "
        f"{figures['loop_own_lag_max_s_loaded']} s (idle: {figures['loop_lag_max_s_idle']} s, "
        f"own {figures['loop_own_lag_max_s_idle']} s)"
    )
    for phase in ("burst", "load"):
        if f"{phase}_service_cpu_s" in figures:
            print(
                f"{phase}: service CPU {figures[f'{phase}_service_cpu_s']} s "
                f"({figures[f'{phase}_service_cpu_ms_per_call']} ms a call, "
                f"{figures[f'{phase}_service_cpu_ms_per_event']} ms an event of "
                f"{figures[f'{phase}_events']}); its loop thread "
                f"on a CPU {figures[f'{phase}_loop_thread_on_cpu_s']} s, waiting for one "
                f"{figures[f'{phase}_loop_thread_runqueue_wait_s']} s; load average "
                f"{figures[f'{phase}_load_avg_1min']}"
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
        f"{figures['unsubmitted_instructions']} started by unprompted messages; "
        f"{figures['cancelled_after_drain']} cancelled after the drain"
    )
    for kind, tally in sorted(figures["outcomes_by_kind"].items()):  # type: ignore[attr-defined]
        print(f"  {kind}: {tally}")
    print(json.dumps(figures))


if __name__ == "__main__":
    main()
