"""``assistantx run``: one instruction in the simulated office, its trace printed step by step.

With ``--json`` stdout is exactly one JSON object with ``outcome``, ``steps``, ``actions`` (and
the goal-free facts: messages sent, distance driven, usage), so a script can parse it whole; the
readable trace then goes to stderr. ``--trace-out`` writes the full trace JSON to a file. Names
(``--as``, ``--unavailable``) are matched like any name a person types; errors are one line on
stderr. ``--goal`` says what the requester really wants, as the JSON list of a task's goal
milestones (``[{"holds": ["lee", "stapler:zhang"]}]``): the simulated requester then answers the
assistant's questions from it, as in an evaluation; without it, from the words they wrote.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
from pathlib import Path
from typing import Any, TextIO

from assistantx.adapters.model import model_from_settings
from assistantx.agents.registry import PPDR_REASONERS, needs_llm, reasoner_factory
from assistantx.cli._people import resolve_people
from assistantx.core.errors import AssistantXError, GroundingError, OfficeError
from assistantx.core.goals import parse_milestone
from assistantx.core.office import Office, load_office
from assistantx.core.settings import Settings
from assistantx.core.trace import Trace
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.requester import Wish
from assistantx.sim.run import run_in_sim


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser("run", help="run one instruction in the simulated office")
    p.add_argument("instruction", help="the instruction, in plain words")
    p.add_argument("--as", dest="requester", required=True, help="who asks (person id or name)")
    p.add_argument("--unavailable", default="", help="comma-separated names of absent people")
    p.add_argument(
        "--reasoner",
        choices=list(PPDR_REASONERS),
        default=None,
        help="default: llm when ASSISTANTX_LLM_BASE_URL is set, else symbolic",
    )
    p.add_argument("--office", default=None, help="office YAML (default: the default office)")
    p.add_argument("--max-steps", type=int, default=None)
    p.add_argument("--json", action="store_true", help="end with one JSON summary line")
    p.add_argument("--trace-out", default=None, help="write the full trace JSON here")
    p.add_argument("--quiet", action="store_true", help="do not print the trace")
    p.add_argument(
        "--goal",
        default=None,
        help="what the requester really wants, as JSON goal milestones; they answer questions "
        "from it (default: from the words they wrote)",
    )
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    settings = Settings()
    try:
        office = load_office(args.office or settings.office)
        args.requester, args.unavailable = resolve_people(office, args.requester, args.unavailable)
        args.wish = _wish(office, args.requester, args.goal)
    except (OfficeError, GroundingError, ValueError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    kind = args.reasoner or settings.effective_reasoner
    try:
        summary, trace = asyncio.run(_execute(args, settings, office, kind))
    except GroundingError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except AssistantXError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    if not args.quiet:
        # With --json, stdout holds only the JSON object; the readable trace goes to stderr.
        print_trace(trace, sys.stderr if args.json else sys.stdout)
    if args.trace_out:
        Path(args.trace_out).write_text(trace.model_dump_json(indent=2))
    if args.json:
        print(json.dumps(summary))
    return 0 if trace.outcome in ("done", "unachievable") else 1


def _wish(office: Office, requester: str, goal: str | None) -> Wish | None:
    """The requester's wish from ``--goal`` (JSON milestones, each checked), or None."""
    if goal is None:
        return None
    try:
        milestones = json.loads(goal)
    except json.JSONDecodeError as exc:
        raise ValueError(f"--goal is no JSON: {exc}") from exc
    if not isinstance(milestones, list) or not milestones:
        raise ValueError("--goal is a JSON list of milestones")
    for milestone in milestones:
        parse_milestone(milestone)
    return Wish.from_goal(office, requester, milestones)


async def _execute(
    args: argparse.Namespace, settings: Settings, office: Any, kind: str
) -> tuple[dict[str, Any], Trace]:
    unavailable: tuple[str, ...] = args.unavailable
    limits = LoopLimits(
        max_steps=args.max_steps or settings.max_steps,
        deadline_s=settings.instruction_deadline_s,
        wall_s=settings.instruction_wall_s,
    )
    run = await run_in_sim(
        office,
        args.requester,
        args.instruction,
        reasoner_factory(
            kind,
            office,
            settings,
            model=model_from_settings(settings) if needs_llm(kind) else None,
        ),
        unavailable=unavailable,
        limits=limits,
        reasoner_name=kind,
        wish=args.wish,
    )
    sim = run.sim
    trace = run.trace
    actions = [r.action.model_dump(mode="json") for r in trace.actions()]
    summary = {
        "instruction_id": trace.instruction_id,
        "requester": trace.requester,
        "reasoner": kind,
        "outcome": trace.outcome,
        "summary": trace.summary,
        "steps": len(trace.steps),
        "actions": actions,
        "refused": sum(1 for r in trace.actions() if r.refused),
        "sim_time_s": round(sim.clock.now(), 1),
        "distance_m": round(sim.robot.odometer_m, 1),
        "llm_calls": trace.usage.llm_calls,
        "prompt_tokens": trace.usage.prompt_tokens,
        "completion_tokens": trace.usage.completion_tokens,
    }
    return summary, trace


def print_trace(trace: Trace, out: TextIO = sys.stdout) -> None:
    print(f"instruction {trace.instruction_id} from {trace.requester}: {trace.text!r}", file=out)
    for step in trace.steps:
        print(f"-- step {step.index}", file=out)
        if step.percept and step.percept.summary:
            print(f"   percept: {step.percept.summary}", file=out)
        if step.plan:
            todo = [("[x] " if s.done else "[ ] ") + s.description for s in step.plan.subgoals]
            print(f"   plan: {step.plan.goal}", file=out)
            for line in todo:
                print(f"     {line}", file=out)
        for f in step.feedback:
            print(f"   feedback: {f}", file=out)
        for r in step.results:
            status = "refused" if r.refused else ("ok" if r.ok else "failed")
            print(f"   t={r.started_at:6.0f}s {r.action.signature()}", file=out)
            print(f"            -> {status}: {r.observation}", file=out)
        if step.reflection:
            print(f"   reflection {step.reflection.verdict}: {step.reflection.reason}", file=out)
            for applied in step.applied:
                print(f"     memory: {applied.update.model_dump(exclude={'evidence'})}", file=out)
        if step.queue:
            print(f"   queued behind: {', '.join(step.queue)}", file=out)
    print(f"outcome: {trace.outcome} — {trace.summary}", file=out)
    if trace.usage.llm_calls:
        u = trace.usage
        print(
            f"llm: {u.calls} calls, {u.prompt_tokens}+{u.completion_tokens} tokens, "
            f"{u.latency_s:.1f} s",
            file=out,
        )
