"""Reasoning time of the embedded symbolic reasoner, per step and per instruction.

Runs every kind of instruction at its levels (L1, L2, L3, unachievable) in the simulated
office and measures the time spent inside the four agents (Perception, Planning, Decision,
Reflection) as recorded in the trace; simulated travel and waiting cost no real time and are
excluded. Also times the instruction parser alone over the paraphrase set. Prints one line
per instruction, then the medians; the last line is one JSON object.

    python bench/symbolic_speed.py [--repeat N]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import time
from pathlib import Path

import yaml

from assistantx.agents.symbolic import InstructionParser, build_factory
from assistantx.core.office import Office, load_office
from assistantx.core.settings import Settings
from assistantx.core.trace import Trace
from assistantx.sim.run import run_in_sim

# (requester, instruction, unavailable people)
INSTRUCTIONS: list[tuple[str, str, tuple[str, ...]]] = [
    ("lee", "bring me a stapler", ()),
    ("lee", "could you get me a stapler?", ("wang",)),
    ("lee", "I need a stapler", ("wang", "zhang")),
    ("lee", "bring me a stapler", ("wang", "zhang", "hu", "gao")),
    ("lee", "bring me Yang's book", ()),
    ("lee", "bring me Yang's book", ("yang",)),
    ("lee", "take my book to Wang", ()),
    ("lee", "print my file and bring it to me", ()),
    ("lee", "please print my slides", ("mao",)),
    ("lee", "print my file", ("mao", "xu")),
    ("lee", "make a copy of my contract", ()),
    ("lee", "get Zhang to sign my contract", ()),
    ("lee", "get Zhang to sign my contract", ("zhang",)),
    ("lee", "get my contract stamped with the company seal", ()),
    ("lee", "get my contract stamped with the company seal", ("wang", "mao")),
    ("lee", "get my contract stamped with the company seal", ("wang", "mao", "sun")),
    ("lee", "make me a coffee", ()),
    ("lee", "I'd love a latte", ("gao",)),
    ("lee", "grab me a glass of water", ()),
    ("lee", "buy me a soda from the vending machine", ()),
    ("lee", "heat up my lunch", ()),
    ("lee", "warm up my leftovers", ("chen", "hu")),
    ("lee", "send my slides to Zhou", ()),
    ("lee", "get Wang's report file for me", ()),
    ("lee", "print my file and take it to Wang", ()),
    ("lee", "Could you heat up my lunch and then make me a coffee?", ()),
    ("zhang", "Please find me a book to read over lunch.", ()),
    ("lin", "Bring me a stapler and a coffee, please.", ()),
    ("lee", "Bring me a stapler and a coffee, please.", ("wang", "zhang", "hu", "gao")),
    ("lee", "bring me scissors, a pen and some wipes", ()),
    ("lee", "bring me the thing", ()),
]
PARAPHRASES = Path(__file__).resolve().parent.parent / "tests" / "symbolic" / "paraphrases.yaml"


async def run_one(office: Office, requester: str, text: str, away: tuple[str, ...]) -> Trace:
    run = await run_in_sim(
        office, requester, text, build_factory(office, Settings()), unavailable=away
    )
    return run.trace


async def main(repeat: int) -> dict[str, object]:
    office = load_office()
    per_step_ms: list[float] = []
    per_instruction_ms: list[float] = []
    wall_ms: list[float] = []
    outcomes: dict[str, int] = {}
    for _ in range(repeat):
        for requester, text, away in INSTRUCTIONS:
            started = time.perf_counter()
            trace = await run_one(office, requester, text, away)
            wall = (time.perf_counter() - started) * 1000
            steps = [sum(c.latency_s for c in s.calls) * 1000 for s in trace.steps if s.calls]
            per_step_ms += steps
            per_instruction_ms.append(sum(steps))
            wall_ms.append(wall)
            outcome = trace.outcome or "none"
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
            label = f"{text!r} away={','.join(away) or '-'}"
            print(
                f"{label:75.75} {outcome:12} steps={len(steps):2d} "
                f"reasoning={sum(steps):7.2f} ms  wall={wall:7.1f} ms"
            )
    parser = InstructionParser(office)
    parse_us: list[float] = []
    for case in yaml.safe_load(PARAPHRASES.read_text(encoding="utf-8")):
        for _ in range(repeat):
            started = time.perf_counter()
            parser.parse(case["text"], case.get("as", "lee"))
            parse_us.append((time.perf_counter() - started) * 1e6)
    result = {
        "instructions": len(per_instruction_ms),
        "steps": len(per_step_ms),
        "median_step_ms": round(statistics.median(per_step_ms), 3),
        "p95_step_ms": round(sorted(per_step_ms)[int(0.95 * (len(per_step_ms) - 1))], 3),
        "max_step_ms": round(max(per_step_ms), 3),
        "median_instruction_reasoning_ms": round(statistics.median(per_instruction_ms), 3),
        "median_instruction_wall_ms": round(statistics.median(wall_ms), 3),
        "outcomes": outcomes,
        "paraphrases_parsed": len(parse_us) // repeat,
        "median_parse_us": round(statistics.median(parse_us), 1),
        "max_parse_us": round(max(parse_us), 1),
    }
    print(
        f"median per step {result['median_step_ms']} ms (p95 {result['p95_step_ms']} ms, "
        f"max {result['max_step_ms']} ms); median per instruction "
        f"{result['median_instruction_reasoning_ms']} ms reasoning, "
        f"{result['median_instruction_wall_ms']} ms wall; parsing alone: median "
        f"{result['median_parse_us']} us, max {result['max_parse_us']} us"
    )
    return result


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print(json.dumps(asyncio.run(main(args.repeat))))
