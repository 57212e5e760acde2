"""``assistantx eval``: run a method over a task file in the simulated office and score it.

Writes ``results.jsonl`` (one scored episode per line, appended as each finishes, so an
interrupted run resumes), ``summary.json``, ``summary.md`` and one PNG chart per metric.
A progress line with the running SR goes to stderr.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from assistantx.adapters.model import model_from_settings
from assistantx.agents.registry import PPDR_REASONERS
from assistantx.core.errors import AssistantXError
from assistantx.core.settings import Settings
from assistantx.evaluation.episode import Episode
from assistantx.evaluation.harness import EvalConfig, Progress, evaluate, load_episodes
from assistantx.evaluation.methods import METHODS, METRICS_HELP
from assistantx.evaluation.report import write_report


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser("eval", help="evaluate a method on a task file", description=METRICS_HELP)
    p.add_argument("--tasks", required=True, help="task file (JSON lines, DESIGN §5)")
    p.add_argument("--method", choices=METHODS, default="ppdr")
    p.add_argument("--reasoner", choices=list(PPDR_REASONERS), default=None)
    p.add_argument("--runs", type=int, default=1)
    p.add_argument("--levels", default="", help="comma-separated, e.g. L1,L2")
    p.add_argument("--limit", type=int, default=None, help="only the first N tasks")
    p.add_argument("--jobs", type=int, default=1, help="episodes in parallel processes")
    p.add_argument("--office", default=None, help="default: office.yaml beside the tasks")
    p.add_argument("--max-steps", type=int, default=None)
    p.add_argument("--out", default=None, help="default: results/<method>-<time>")
    p.add_argument("--quiet", action="store_true", help="no progress line")
    p.set_defaults(func=_eval)


def _progress_line(episode: Episode, progress: Progress) -> None:
    width = 30
    total = max(1, progress.total - progress.skipped)
    filled = int(width * progress.done / total)
    elapsed = time.monotonic() - progress.started
    sys.stderr.write(
        f"\r[{'#' * filled}{'.' * (width - filled)}] {progress.done}/{total} "
        f"SR {100 * progress.sr:5.1f}%  {elapsed:6.1f}s  {episode.task_id} run {episode.run} "
    )
    sys.stderr.flush()


def _eval(args: argparse.Namespace) -> int:
    settings = Settings()
    if args.runs < 1 or args.jobs < 1:
        print("error: --runs and --jobs must be at least 1")
        return 2
    reasoner = args.reasoner or settings.effective_reasoner
    stamp = time.strftime("%Y%m%d-%H%M%S")
    out = Path(args.out or f"results/{args.method}-{stamp}")
    config = EvalConfig(
        tasks=Path(args.tasks),
        out=out,
        method=args.method,
        reasoner=reasoner,
        runs=args.runs,
        levels=tuple(x.strip() for x in args.levels.split(",") if x.strip()),
        limit=args.limit,
        jobs=args.jobs,
        office=Path(args.office) if args.office else None,
        max_steps=args.max_steps or settings.max_steps,
    )
    try:
        tasks = evaluate(
            config,
            settings,
            None if args.quiet else _progress_line,
            build_model=model_from_settings,
        )
    except AssistantXError as exc:
        print(f"error: {exc}")
        return 2
    if not args.quiet:
        sys.stderr.write("\n")
    wanted = {t.id for t in tasks}
    episodes = [e for e in load_episodes(out) if e.task_id in wanted and e.run < config.runs]
    summary = write_report(episodes, config.spec.label, out)
    print((out / "summary.md").read_text(encoding="utf-8"), end="")
    print(f"results in {out}/ (results.jsonl, summary.json, summary.md, *.png)")
    del summary
    return 0
