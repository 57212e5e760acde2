"""A year of use in minutes: journal size and resident memory per 1,000 instructions.

Runs the service's runtime in this process (the kinematic robot, simulated colleagues, the
embedded reasoner, simulated time sped up) and submits the 30 base instructions in turn, in
concurrent batches, until ``--n`` have ended. After every ``--every`` instructions it records
the journal's size on disk (database + WAL), the resident memory (after a full collection)
and the number of live objects. At the end it times a replay of every journaled event (what
an unbounded ``GET /v1/events`` read), the default bounded replay, and a restart: the runtime
stopped and a new one started on the same journal (in this process, and as a fresh
``assistantx serve`` process timed until ``/readyz`` answers, imports included). Writes
``journal_growth.png`` (``--out``); the last line is one JSON object.

    python bench/journal_growth.py [--n 10000] [--every 1000] [--batch 50] [--out DIR]
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import json
import os
import sys
import tempfile
import time
from contextlib import AsyncExitStack
from pathlib import Path

import httpx
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))

from instructions_10k import (
    Server,
    process_cpu_s,
)  # the served process, as the 10,000 bench runs it

from assistantx.core.office import DEFAULT_OFFICE
from assistantx.core.settings import Settings
from assistantx.service.events import REPLAY_DEFAULT
from assistantx.service.runtime import JOURNAL_FILE, ServiceRuntime

BASES = DEFAULT_OFFICE.parent / "base_instructions.yaml"
SPEEDUP = 1000.0  # as bench/service_load.py: faster, and replies miss their waits


def _rss_mb() -> float:
    pages = int(Path("/proc/self/statm").read_text().split()[1])
    return pages * os.sysconf("SC_PAGE_SIZE") / 2**20


def _journal_mb(data: Path) -> float:
    files = [data / JOURNAL_FILE, data / f"{JOURNAL_FILE}-wal"]
    return sum(f.stat().st_size for f in files if f.exists()) / 2**20


def _settings(data: Path) -> Settings:
    return Settings(
        data_dir=data,
        robot="sim",
        speedup=SPEEDUP,
        sim_reply_delay_s=5,
        sim_handover_delay_s=5,
        instruction_deadline_s=30 * 24 * 3600,
    )


async def _drive(runtime: ServiceRuntime, n: int, batch: int, every: int) -> list[dict]:
    bases = yaml.safe_load(BASES.read_text(encoding="utf-8"))["instructions"]
    rows: list[dict] = []
    submitted = 0
    started = time.perf_counter()
    while submitted < n:
        ids = []
        for _ in range(min(batch, n - submitted)):
            base = bases[submitted % len(bases)]
            ids.append((await runtime.submit(base["requester"], base["text"])).id)
            submitted += 1
        while runtime.admission.waiting or runtime.assistant.running:  # noqa: ASYNC110 - polls state it does not own
            await asyncio.sleep(0.02)
        if submitted % every == 0:
            gc.collect()
            row = {
                "instructions": submitted,
                "journal_mb": round(_journal_mb(runtime.journal.path.parent), 2),
                "rss_mb": round(_rss_mb(), 1),
                "objects": len(gc.get_objects()),
                "wall_s": round(time.perf_counter() - started, 1),
            }
            rows.append(row)
            print(
                f"{submitted:6d} instructions: journal {row['journal_mb']} MB, RSS "
                f"{row['rss_mb']} MB, {row['objects']} objects ({row['wall_s']} s)",
                flush=True,
            )
    return rows


def restart_serve(data: Path, log: Path) -> dict[str, float]:
    """``assistantx serve`` on ``data``'s journal: CPU-seconds and wall seconds to ready."""
    args = argparse.Namespace(speedup=SPEEDUP, robot="sim")
    with httpx.Client() as client:
        server = Server.start(data, args, log)
        try:
            wall = server.wait_ready(client)
            return {"cpu_s": round(process_cpu_s(server.process.pid), 2), "wall_s": round(wall, 2)}
        finally:
            server.stop()


def _replay_s(runtime: ServiceRuntime, after: int) -> tuple[float, int]:
    started, seen, last = time.perf_counter(), 0, after
    while page := runtime.journal.events(after_seq=last, limit=500):
        seen += len(page)
        last = page[-1].seq
        for record in page:  # what the stream does with each: encode it
            json.dumps(record.event.model_dump(mode="json"))
    return time.perf_counter() - started, seen


async def _run(args: argparse.Namespace, data: Path) -> dict[str, object]:
    async with AsyncExitStack() as stack:
        runtime = ServiceRuntime(_settings(data))
        await runtime.start(stack)
        rows = await _drive(runtime, args.n, args.batch, args.every)
        full_s, events = _replay_s(runtime, 0)
        newest = runtime.journal.last_event_seq()
        bounded_s, _ = _replay_s(runtime, max(0, newest - REPLAY_DEFAULT))
        outcomes = runtime.journal.count_by_status()
    started = time.perf_counter()
    async with AsyncExitStack() as stack:
        again = ServiceRuntime(_settings(data))
        await again.start(stack)
        runtime_start_s = time.perf_counter() - started
    first, last = rows[0], rows[-1]
    return {
        "n": args.n,
        "rows": rows,
        "journal_kb_per_instruction": round(1024 * last["journal_mb"] / last["instructions"], 1),
        "rss_growth_after_first_pct": round(100 * (last["rss_mb"] / first["rss_mb"] - 1), 1),
        "objects_growth_after_first_pct": round(100 * (last["objects"] / first["objects"] - 1), 1),
        "events": events,
        "replay_all_s": round(full_s, 2),
        "replay_default_s": round(bounded_s, 3),
        "runtime_start_s": round(runtime_start_s, 2),
        "statuses": outcomes,
    }


def _plot(result: dict, out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = result["rows"]
    xs = [r["instructions"] for r in rows]
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
    for ax, key, title in zip(
        axes,
        ("journal_mb", "rss_mb", "objects"),
        ("journal on disk (MB)", "resident memory (MB)", "live objects"),
        strict=True,
    ):
        ax.plot(xs, [r[key] for r in rows], marker="o")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("instructions")
        ax.set_ylim(bottom=0)
    fig.tight_layout()
    path = out / "journal_growth.png"
    fig.savefig(path, dpi=100)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10_000)
    parser.add_argument("--every", type=int, default=1000)
    parser.add_argument("--batch", type=int, default=100)
    parser.add_argument("--out", type=Path, default=Path("results/bench"))
    args = parser.parse_args()
    if args.n % args.every or args.every % args.batch:
        parser.error("--n must be a multiple of --every, and --every of --batch")
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        result = asyncio.run(_run(args, Path(tmp) / "data"))
        result["restart_s"] = restart_serve(
            Path(tmp) / "data", args.out / "journal_growth-server.log"
        )["wall_s"]
    result["plot"] = str(_plot(result, args.out))
    print(
        f"journal {result['journal_kb_per_instruction']} KB per instruction; RSS growth after "
        f"the first {args.every}: {result['rss_growth_after_first_pct']}%; replaying all "
        f"{result['events']} events {result['replay_all_s']} s, the default replay "
        f"{result['replay_default_s']} s; restart to ready {result['restart_s']} s"
    )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
