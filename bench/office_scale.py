"""Cost against office size: generated offices of 16 to 1,024 people.

For each size the default office is replicated (``bench/_office_gen.py``) and measured:
loading the office file, the embedded reasoner's time per instruction (median) and per step
(p95) over a fixed set of instructions whose requesters exist at every size, the long-term
memory rendered for a prompt (tokens estimated as characters / 4; the LLM helper's focus
rendering is what bounds it), and the process's resident memory after the size ran. Writes
``office_scale.png`` (``--out``); the last line is one JSON object.

    python bench/office_scale.py [--sizes 16,64,256,1024] [--repeat 1] [--out DIR]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _office_gen import write_office

from assistantx.agents.symbolic import build_factory
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.render import render_long_term
from assistantx.sim.run import run_in_sim

# (requester, instruction, unavailable people): L1, L2 and L3 kinds, people of the 16 originals.
INSTRUCTIONS: list[tuple[str, str, tuple[str, ...]]] = [
    ("lee", "bring me a stapler", ()),
    ("lee", "could you get me a stapler?", ("wang",)),
    ("lee", "bring me Yang's book", ()),
    ("lee", "print my file and bring it to me", ()),
    ("lee", "get Zhang to sign my contract", ()),
    ("lee", "make me a coffee", ()),
    ("lee", "send my slides to Zhou", ()),
    ("lin", "Bring me a stapler and a coffee, please.", ()),
]


def _rss_mb() -> float:
    pages = int(Path("/proc/self/statm").read_text().split()[1])
    return pages * 4096 / 2**20


async def _measure(path: Path, repeat: int) -> dict[str, float]:
    started = time.perf_counter()
    office = load_office(path)
    load_s = time.perf_counter() - started
    factory = build_factory(office, Settings())
    per_instruction: list[float] = []
    per_step: list[float] = []
    for _ in range(repeat):
        for requester, text, away in INSTRUCTIONS:
            run = await run_in_sim(office, requester, text, factory, unavailable=away)
            steps = [sum(c.latency_s for c in s.calls) * 1000 for s in run.trace.steps]
            per_step += steps
            per_instruction.append(sum(steps))
    prompt_chars = len(render_long_term(LongTermMemory(office)))
    return {
        "people": len(office.people),
        "load_s": round(load_s, 3),
        "instruction_median_ms": round(statistics.median(per_instruction), 2),
        "step_p95_ms": round(sorted(per_step)[int(0.95 * (len(per_step) - 1))], 2),
        "prompt_tokens": prompt_chars // 4,
        "rss_mb": round(_rss_mb(), 1),
    }


def _plot(rows: list[dict[str, float]], out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sizes = [r["people"] for r in rows]
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.6))
    panels = [
        ("load_s", "office load (s)"),
        ("instruction_median_ms", "per instruction, median (ms)"),
        ("step_p95_ms", "per step, p95 (ms)"),
        ("prompt_tokens", "memory in the prompt (tokens)"),
    ]
    for ax, (key, title) in zip(axes, panels, strict=True):
        ax.plot(sizes, [r[key] for r in rows], marker="o")
        ax.set_xscale("log", base=2)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("people")
    fig.tight_layout()
    path = out / "office_scale.png"
    fig.savefig(path, dpi=100)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="16,64,256,1024")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--out", type=Path, default=Path("results/bench"))
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rows: list[dict[str, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        for size in (int(s) for s in args.sizes.split(",")):
            path = write_office(size, Path(tmp) / f"office-{size}.yaml")
            row = asyncio.run(_measure(path, args.repeat))
            rows.append(row)
            print(
                f"{size:5d} people: load {row['load_s']} s, per instruction "
                f"{row['instruction_median_ms']} ms (median), step p95 {row['step_p95_ms']} ms,"
                f" memory prompt {row['prompt_tokens']} tokens, RSS {row['rss_mb']} MB"
            )
    plot = _plot(rows, args.out)
    print(json.dumps({"sizes": rows, "plot": str(plot)}))


if __name__ == "__main__":
    main()
