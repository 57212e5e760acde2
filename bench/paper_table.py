"""The paper's comparison in one command, against any OpenAI-compatible server.

Runs PPDR with the LLM agents, the hybrid reasoner, the three ablations and the five
baselines on a few tasks of each level (``--per-level``, default 2, so 6 tasks) in the
simulated office, scores them with the evaluator's metrics and writes the table in the paper's
layout: SR / CR / RR / CTA / RTA per level, plus LLM calls, tokens and model latency per task.

    python bench/paper_table.py --base-url http://127.0.0.1:8080/v1 --model NAME \\
        [--tasks dataset/tasks.jsonl] [--per-level 2] [--max-steps 8] [--wall-s 300] \\
        [--max-tokens 512] [--context 8192] [--methods ppdr,hybrid,...] [--out DIR] \\
        [--concurrency 8] [--call-budget-s 120]

``--concurrency N`` runs N episodes of a method at once against the one server (a GPU server
batches them); ``--wall-s`` bounds each episode (``ASSISTANTX_INSTRUCTION_WALL_S`` unless
given) and ``--call-budget-s`` each model call (``ASSISTANTX_LLM_CALL_BUDGET_S`` unless
given). Token counts the server did not report are estimates and are marked ``~``. Writes
DIR/paper_table.md and DIR/paper_table.json (default DIR: results/paper_table); the last
stdout line is one JSON object with every method's figures, its wall time and the server's
completion tokens per second.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import time
from pathlib import Path
from typing import Any

from assistantx.adapters.model import model_from_settings
from assistantx.agents.ablations import ABLATIONS
from assistantx.agents.baseline_names import BASELINES
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset.tasks import Task, load_tasks
from assistantx.evaluation.episode import Episode
from assistantx.evaluation.harness import run_episode
from assistantx.evaluation.methods import MethodBuilder, MethodSpec
from assistantx.evaluation.report import summarize

REPO = Path(__file__).resolve().parents[1]
METHODS: dict[str, MethodSpec] = {
    "ppdr": MethodSpec("ppdr", "llm"),
    "hybrid": MethodSpec("ppdr", "hybrid"),
    **{name: MethodSpec(name, "llm") for name in ABLATIONS},
    **{name: MethodSpec(name) for name in BASELINES},
}
LEVELS = ("L1", "L2", "L3")


def pick_tasks(tasks: list[Task], per_level: int) -> list[Task]:
    """The first ``per_level`` tasks of each level, each from a different base instruction."""
    picked: list[Task] = []
    for level in LEVELS:
        bases: set[str] = set()
        for task in tasks:
            if task.level == level and task.base not in bases and len(bases) < per_level:
                bases.add(task.base)
                picked.append(task)
    return picked


async def run_method(
    name: str, tasks: list[Task], settings: Settings, args: argparse.Namespace
) -> list[Episode]:
    """Every task of one method, ``args.concurrency`` episodes at a time, one shared model."""
    office = load_office()
    builder = MethodBuilder(METHODS[name], office, settings, build_model=model_from_settings)
    slots = asyncio.Semaphore(max(1, args.concurrency))

    async def one(task: Task) -> Episode:
        async with slots:
            started = time.perf_counter()
            episode = await run_episode(
                task, 0, office, builder, args.max_steps, wall_s=settings.instruction_wall_s
            )
        usage = episode.trace.usage
        print(
            f"{name:>20} {task.id} {task.level}: {episode.trace.outcome}, "
            f"{usage.llm_calls} calls, {'~' if usage.estimated else ''}"
            f"{usage.prompt_tokens}+{usage.completion_tokens} tokens, "
            f"{time.perf_counter() - started:.0f} s",
            flush=True,
        )
        return episode.model_copy(update={"method": name})

    # the shared model opens with the first reasoner and closes with the last
    return list(await asyncio.gather(*(one(task) for task in tasks)))


def _pct(cell: dict[str, Any] | None) -> str:
    value = cell.get("mean") if cell else None
    return "–" if value is None else f"{100 * value:.0f}"


def _num(cell: dict[str, Any] | None, digits: int = 0) -> str:
    value = cell.get("mean") if cell else None
    return "–" if value is None else f"{value:.{digits}f}"


def table(summaries: dict[str, dict[str, Any]], model: str, n_tasks: int) -> str:
    head = ["method"]
    for level in LEVELS:
        head += [f"{level} {m}" for m in ("SR", "CR", "RR", "CTA", "RTA")]
    head += ["calls/task", "tokens/task", "model s/task", "server tok/s"]
    lines = [
        f"Model: `{model}`; {n_tasks} tasks (per level: SR, CR, RR, CTA, RTA in %; "
        "calls, prompt+completion tokens and model latency per task over all levels; the "
        "server's completion tokens per second of the method's wall time; ~: estimated).",
        "",
        "| " + " | ".join(head) + " |",
        "|" + "---|" * len(head),
    ]
    for name, summary in summaries.items():
        levels = summary["levels"]
        row = [name]
        for level in LEVELS:
            entry = levels.get(level, {})
            row += [_pct(entry.get(m)) for m in ("sr", "cr", "rr", "cta", "rta")]
        every = levels.get("all", {})
        prompt = (every.get("prompt_tokens") or {}).get("mean") or 0.0
        completion = (every.get("completion_tokens") or {}).get("mean") or 0.0
        mark = "~" if summary.get("estimated") else ""
        row += [
            _num(every.get("llm_calls"), 1),
            f"{mark}{prompt + completion:.0f}",
            _num(every.get("model_s"), 1),
            f"{mark}{summary.get('server_tokens_per_s') or 0:.1f}",
        ]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base-url", required=True, help="OpenAI-compatible /v1 URL")
    parser.add_argument("--model", required=True)
    parser.add_argument("--api-key", default=None)
    parser.add_argument("--tasks", type=Path, default=REPO / "dataset" / "tasks.jsonl")
    parser.add_argument("--per-level", type=int, default=2)
    parser.add_argument("--methods", default=",".join(METHODS))
    parser.add_argument("--max-steps", type=int, default=8)
    parser.add_argument("--wall-s", type=float, default=None, help="wall bound per episode")
    parser.add_argument("--max-tokens", type=int, default=512)
    parser.add_argument("--context", type=int, default=8192)
    parser.add_argument("--call-budget-s", type=float, default=None, help="wall bound per call")
    parser.add_argument("--concurrency", type=int, default=1, help="episodes at once")
    parser.add_argument("--out", type=Path, default=REPO / "results" / "paper_table")
    args = parser.parse_args()
    unknown = [m for m in args.methods.split(",") if m not in METHODS]
    if unknown:
        parser.error(f"unknown method(s) {unknown}; choose from {', '.join(METHODS)}")
    if args.concurrency < 1:
        parser.error("--concurrency must be at least 1")
    result = asyncio.run(paper_table(args))
    print(result["table"])
    del result["table"]
    print(json.dumps(result))


def settings_for(args: argparse.Namespace) -> Settings:
    """The settings of the run: the environment's, with what the command line gives."""
    overrides: dict[str, Any] = {
        "llm_base_url": args.base_url,
        "llm_model": args.model,
        "llm_max_tokens": args.max_tokens,
        "llm_context_tokens": args.context,
    }
    if args.api_key is not None:
        overrides["llm_api_key"] = args.api_key
    if args.wall_s is not None:
        overrides["instruction_wall_s"] = args.wall_s
    if args.call_budget_s is not None:
        overrides["llm_call_budget_s"] = args.call_budget_s
        overrides["llm_timeout_s"] = args.call_budget_s
    return Settings(**overrides)


async def paper_table(args: argparse.Namespace) -> dict[str, Any]:
    """Runs every method; writes the table files; returns the figures (and the table)."""
    settings = settings_for(args)
    tasks = pick_tasks(load_tasks(args.tasks, load_office()), args.per_level)
    summaries: dict[str, dict[str, Any]] = {}
    walls: dict[str, float] = {}
    for name in args.methods.split(","):
        started = time.perf_counter()
        episodes = await run_method(name, tasks, settings, args)
        walls[name] = time.perf_counter() - started
        summary = summarize(episodes, name)
        model_s = sum(e.trace.usage.latency_s for e in episodes) / max(1, len(episodes))
        summary["levels"].setdefault("all", {})["model_s"] = {"mean": model_s}
        completion = sum(e.trace.usage.completion_tokens for e in episodes)
        summary["server_tokens_per_s"] = completion / walls[name] if walls[name] > 0 else None
        summary["estimated"] = any(e.trace.usage.estimated for e in episodes)
        summary["wall_s"] = walls[name]
        summaries[name] = summary
    text = table(summaries, args.model, len(tasks))
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "paper_table.md").write_text(text + "\n", encoding="utf-8")
    (args.out / "paper_table.json").write_text(json.dumps(summaries, indent=1), encoding="utf-8")
    return {
        "table": text,
        "model": args.model,
        "concurrency": args.concurrency,
        "tasks": [t.id for t in tasks],
        "call_budget_s": settings.llm_call_budget_s,
        "instruction_wall_s": settings.instruction_wall_s,
        "methods": {
            name: {
                "wall_s": round(s["wall_s"], 2),
                "server_tokens_per_s": s["server_tokens_per_s"],
                "estimated": s["estimated"],
                **{
                    level: {
                        k: (v.get("mean") if isinstance(v, dict) else v) for k, v in entry.items()
                    }
                    for level, entry in s["levels"].items()
                },
            }
            for name, s in summaries.items()
        },
    }


if __name__ == "__main__":
    main()
