"""Run a file of phrasings one by one through the simulated office and judge each run against
the writer's expected outcome (the file format and the rules: docs/phrasings.md).

Each case is one ``assistantx run --as P --json --quiet --office O --reasoner symbolic
--trace-out T [--goal G] TEXT`` in its own process, with this interpreter and the current
PYTHONPATH (``--src`` puts a source tree first on it), so it measures whichever code that path
holds. A deliver case's requester answers the assistant's questions from the case's truth
(``--goal``: recipient, item, owner), an ask, words or decline case's from their words only::

    python bench/phrasings.py --phrasings FILE.yaml [--jobs 2] [--label L] [--out DIR]
        [--src SRC] [--office O] [--timeout-s 120]

One line per case (id, expected, got, right or WRONG, and why), a summary, and last one JSON
object ``{"label", "cases", "right", "wrong_physical", "by_expect", "wrong"}``. With ``--out``
each case's trace is kept as ``DIR/traces/<id>.json`` beside ``DIR/results.json``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from _phrasing_judge import Case, PhrasingsError, Verdict, judge, load_phrasings, truth_goal

from assistantx.core.office import Office


@dataclass(frozen=True)
class Result:
    id: str
    expect: str
    verdict: Verdict
    summary: str  # what the assistant told the requester, or why the run gave no trace


def run_case(
    case: Case, office: Office, office_path: Path, env: dict[str, str], args: argparse.Namespace
) -> tuple[Result, dict[str, Any] | None]:
    with tempfile.TemporaryDirectory(prefix="phrasing-") as tmp:
        trace_file = Path(tmp) / "trace.json"
        command = [
            sys.executable,
            "-m",
            "assistantx",
            "run",
            "--as",
            case.as_,
            "--json",
            "--quiet",
            "--office",
            str(office_path),
            "--reasoner",
            "symbolic",
            "--trace-out",
            str(trace_file),
            *_goal_option(case),
            "--",  # a text that starts with a dash is still the instruction
            case.text,
        ]
        try:
            done = subprocess.run(
                command, env=env, capture_output=True, text=True, timeout=args.timeout_s
            )
        except subprocess.TimeoutExpired:
            return _no_trace(case, f"no trace: timed out after {args.timeout_s:g} s"), None
        if not trace_file.exists():
            error = (done.stderr.strip().splitlines() or [f"exit {done.returncode}"])[-1]
            return _no_trace(case, f"no trace: {error}"), None
        trace: dict[str, Any] = json.loads(trace_file.read_text())
    verdict = judge(case, trace, office)
    return Result(case.id, case.expect, verdict, trace.get("summary") or ""), trace


def _goal_option(case: Case) -> list[str]:
    """``--goal`` with a deliver case's truth, so the requester answers as one who wants it."""
    goal = truth_goal(case)
    return [] if goal is None else ["--goal", json.dumps(goal)]


def _no_trace(case: Case, why: str) -> Result:
    return Result(case.id, case.expect, Verdict("none", False, None, why), why)


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--phrasings", type=Path, required=True, help="the phrasings YAML")
    parser.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    parser.add_argument("--label", default="", help="a name for this run, echoed in the JSON")
    parser.add_argument("--out", type=Path, default=None, help="keep traces and results.json")
    parser.add_argument("--src", default=None, help="a source tree to put first on PYTHONPATH")
    parser.add_argument("--office", default=None, help="office YAML (default: the file's)")
    parser.add_argument("--timeout-s", type=float, default=120.0, help="wall bound per case")
    args = parser.parse_args()
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    try:
        phrasings, office, office_path = load_phrasings(args.phrasings, args.office)
    except PhrasingsError as exc:
        sys.exit(f"error: {exc}")

    env = dict(os.environ)
    if args.src:
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (str(Path(args.src).resolve()), env.get("PYTHONPATH")) if p
        )
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        runs = list(
            pool.map(
                lambda c: run_case(c, office, office_path.resolve(), env, args), phrasings.cases
            )
        )

    by_expect: dict[str, Counter[str]] = {}
    for result, _ in runs:
        v = result.verdict
        tally = by_expect.setdefault(result.expect, Counter({"cases": 0, "right": 0}))
        tally["cases"] += 1
        tally["right"] += v.right
        tally["wrong_physical"] += v.wrong_physical is not None
        line = f"{result.id}: expected {result.expect}, got {v.got}, "
        line += "right" if v.right else f"WRONG ({v.why})"
        print(line)
    results = [r for r, _ in runs]
    right = sum(r.verdict.right for r in results)
    physical = sum(r.verdict.wrong_physical is not None for r in results)
    print(f"{right}/{len(results)} right, {physical} wrong physical")
    for expect, tally in by_expect.items():
        print(f"  {expect}: {tally['right']}/{tally['cases']} right")
    report = {
        "label": args.label,
        "cases": len(results),
        "right": right,
        "wrong_physical": physical,
        "by_expect": {e: dict(t) for e, t in by_expect.items()},
        "wrong": [r.id for r in results if not r.verdict.right],
    }
    if args.out:
        _keep(args.out, runs, report)
    print(json.dumps(report))


def _keep(
    out: Path, runs: list[tuple[Result, dict[str, Any] | None]], report: dict[str, Any]
) -> None:
    traces = out / "traces"
    traces.mkdir(parents=True, exist_ok=True)
    for result, trace in runs:
        if trace is not None:
            (traces / f"{result.id}.json").write_text(json.dumps(trace, indent=1))
    per_case = [
        {"id": r.id, "expect": r.expect, **asdict(r.verdict), "summary": r.summary} for r, _ in runs
    ]
    (out / "results.json").write_text(json.dumps({**report, "per_case": per_case}, indent=1))


if __name__ == "__main__":
    main()
