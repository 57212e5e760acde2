"""10,000 instructions through the service's runtime: resident memory flat, restart fast.

The runtime runs in this process, as ``journal_growth.py`` runs it (kinematic robot,
simulated colleagues, the embedded reasoner, simulated time x1000; the 30 base instructions
in turn, in concurrent batches): through ``ServiceRuntime.submit``, the call behind
``POST /v1/instructions``, not over HTTP, whose client and server would share the machine's
two cores with the runtime and measure them instead. Resident memory (after a full
collection) is read after the first ``--every`` instructions and after each ``--every``
more; growth is the last against the first. Then a fresh ``assistantx serve`` process is
started on that journal and timed until ``/readyz`` answers: its own user + system
CPU-seconds (the machine is shared: wall time mostly measures the neighbours) and the wall
time, both reported.

    python bench/instructions_10k.py [--n 10000] [--every 1000] [--batch 100]

Targets (issue 26): RSS growth after the first 1,000 <= 10%; restart to ready <= 3 s.
Last line: one JSON object.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import sys
import tempfile
import time
from contextlib import AsyncExitStack
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from journal_growth import _drive, _settings, restart_serve  # the journal bench's workload

from assistantx.service.runtime import ServiceRuntime

RSS_GROWTH_TARGET_PCT = 10.0
RESTART_TARGET_S = 3.0


async def run(n: int, every: int, batch: int, data: Path) -> dict[str, object]:
    async with AsyncExitStack() as stack:
        # The per-person limit guards a real office; here 30 people send thousands.
        settings = _settings(data).model_copy(update={"instructions_per_minute": 1_000_000})
        runtime = ServiceRuntime(settings)
        await runtime.start(stack)
        started = time.process_time()
        rows = await _drive(runtime, n, batch, every)
        cpu_s = time.process_time() - started
        statuses = runtime.journal.count_by_status()
    first, last = rows[0], rows[-1]
    growth = 100 * (last["rss_mb"] / first["rss_mb"] - 1)
    return {
        "n": n,
        "rss_mb_after_first": first["rss_mb"],
        "rss_mb_at_end": last["rss_mb"],
        "rss_growth_pct": round(growth, 1),
        "rss_ok": growth <= RSS_GROWTH_TARGET_PCT,
        "rows": rows,
        "cpu_s_per_instruction": round(cpu_s / n, 4),
        "statuses": statuses,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10_000)
    parser.add_argument("--every", type=int, default=1000)
    parser.add_argument("--batch", type=int, default=100)
    args = parser.parse_args()
    if args.n % args.every or args.every % args.batch:
        parser.error("--n must be a multiple of --every, and --every of --batch")
    with tempfile.TemporaryDirectory() as tmp:
        data = Path(tmp) / "data"
        result = asyncio.run(run(args.n, args.every, args.batch, data))
        again = restart_serve(data)
    result["restart_cpu_s"], result["restart_wall_s"] = again["cpu_s"], again["wall_s"]
    result["restart_ok"] = again["cpu_s"] <= RESTART_TARGET_S
    result["load_avg_1min"] = round(os.getloadavg()[0], 1)
    print(
        f"{args.n} instructions: RSS {result['rss_mb_after_first']} MB after the first "
        f"{args.every}, {result['rss_mb_at_end']} MB at the end ({result['rss_growth_pct']}%); "
        f"restart to ready {again['cpu_s']} CPU-s ({again['wall_s']} s wall)"
    )
    print(json.dumps(result))


if __name__ == "__main__":
    main()
