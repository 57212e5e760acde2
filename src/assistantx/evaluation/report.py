"""Aggregate scored episodes into the summary: per level, mean ± spread over runs, pass^k.

For each level and each run the metrics are averaged over the level's tasks; the summary
gives the mean and the population standard deviation of those per-run averages. pass^k is
the chance that all of k runs of a task succeed, estimated per task as C(c, k) / C(n, k)
(c successes in n runs) and averaged over tasks.
"""

from __future__ import annotations

import json
import math
import statistics
from collections import defaultdict
from pathlib import Path
from typing import TYPE_CHECKING, Any

from assistantx.evaluation.episode import Episode
from assistantx.evaluation.metrics import Scores, score

if TYPE_CHECKING:  # matplotlib is imported when a chart is drawn: about a CPU-second at start
    from matplotlib.figure import Figure

METRICS = ("sr", "cr", "rr", "cta", "rta")
EXTRAS = ("steps", "actions", "llm_calls", "prompt_tokens", "completion_tokens", "wall_s")
GROUPS = ("L1", "L2", "L3", "all")


def _mean(values: list[float]) -> float | None:
    return sum(values) / len(values) if values else None


def pass_hat_k(successes: list[int], runs: int, k: int) -> float | None:
    if not successes or k > runs:
        return None
    return sum(math.comb(c, k) / math.comb(runs, k) for c in successes) / len(successes)


def summarize(episodes: list[Episode], method: str) -> dict[str, Any]:
    scored: list[tuple[Episode, Scores]] = [(e, score(e)) for e in episodes]
    runs = sorted({e.run for e, _ in scored})
    summary: dict[str, Any] = {"method": method, "runs": len(runs), "levels": {}}
    for group in GROUPS:
        members = [(e, s) for e, s in scored if group in ("all", e.level)]
        if not members:
            continue
        tasks = sorted({e.task_id for e, _ in members})
        entry: dict[str, Any] = {"tasks": len(tasks), "episodes": len(members)}
        for name in (*METRICS, *EXTRAS):
            per_run: list[float] = []
            for run in runs:
                values = [
                    float(v)
                    for e, s in members
                    if e.run == run and (v := getattr(s, name)) is not None
                ]
                m = _mean(values)
                if m is not None:
                    per_run.append(m)
            entry[name] = {
                "mean": _mean(per_run),
                "std": statistics.pstdev(per_run) if len(per_run) > 1 else 0.0,
            }
        by_task: dict[str, int] = defaultdict(int)
        complete: dict[str, int] = defaultdict(int)
        for e, s in members:
            by_task[e.task_id] += int(s.sr)
            complete[e.task_id] += 1
        full = [by_task[t] for t in tasks if complete[t] == len(runs)]
        entry["pass_k"] = {str(k): pass_hat_k(full, len(runs), k) for k in range(1, len(runs) + 1)}
        entry["wrong_handovers"] = sum(s.wrong_handover for _, s in members)
        entry["errors"] = sum(e.error is not None for e, _ in members)
        summary["levels"][group] = entry
    return summary


def _fmt(cell: dict[str, float | None], percent: bool = True, digits: int = 1) -> str:
    mean, std = cell["mean"], cell["std"] or 0.0
    if mean is None:
        return "–"
    if percent:
        return f"{100 * mean:.{digits}f} ± {100 * std:.{digits}f}"
    return f"{mean:.{digits}f} ± {std:.{digits}f}"


def markdown(summary: dict[str, Any]) -> str:
    runs = summary["runs"]
    lines = [
        f"## {summary['method']} — {runs} run(s)",
        "",
        "SR, CR, CTA, RTA and RR in %, mean ± standard deviation over runs.",
        "",
        "| level | tasks | SR | CR | RR | CTA | RTA | pass^" + str(runs) + " | steps | LLM calls "
        "| tokens (prompt+completion) | wall s/task |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for group, e in summary["levels"].items():
        pk = e["pass_k"].get(str(runs))
        tokens_p = e["prompt_tokens"]["mean"] or 0.0
        tokens_c = e["completion_tokens"]["mean"] or 0.0
        lines.append(
            f"| {group} | {e['tasks']} | {_fmt(e['sr'])} | {_fmt(e['cr'])} | {_fmt(e['rr'])} "
            f"| {_fmt(e['cta'])} | {_fmt(e['rta'])} "
            f"| {'–' if pk is None else f'{100 * pk:.1f}'} "
            f"| {_fmt(e['steps'], False)} | {_fmt(e['llm_calls'], False)} "
            f"| {tokens_p:.0f}+{tokens_c:.0f} | {_fmt(e['wall_s'], False, 3)} |"
        )
    all_entry = summary["levels"].get("all", {})
    if all_entry:
        lines += [
            "",
            "Wrong hand-overs (an item to the wrong person, or sent out with no word of where"
            f" to): {all_entry['wrong_handovers']}; episodes the harness could "
            f"not finish: {all_entry['errors']}.",
        ]
    return "\n".join(lines) + "\n"


def chart_data(summary: dict[str, Any], name: str) -> dict[str, Any]:
    """What one metric's chart shows: per level the mean and spread (%), the y range, and a
    note for a chart that would otherwise look empty (RR is often 0 everywhere)."""
    groups = list(summary["levels"])
    means = [100 * (summary["levels"][g][name]["mean"] or 0.0) for g in groups]
    stds = [100 * (summary["levels"][g][name]["std"] or 0.0) for g in groups]
    tops = [m + s for m, s in zip(means, stds, strict=True)]
    # Headroom above the highest bar for its value label, below the chart's title.
    if name == "rr":  # a ratio of redundant actions: small, and unbounded above
        top = max(10.0, *tops) * 1.18
    else:
        top = max(100.0, *tops) * 1.18
    note = None
    if name == "rr" and not any(tops):
        note = "0 redundant actions at every level"
    return {"groups": groups, "means": means, "stds": stds, "ylim": (0.0, top), "note": note}


def chart_figure(summary: dict[str, Any], name: str) -> Figure:
    """One metric's bar chart: a bar per level with the spread over runs, each bar labelled
    with its value (so a zero is visible too) below the title, never over it."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    data = chart_data(summary, name)
    figure = Figure(figsize=(5, 3.2), dpi=100, layout="tight")
    FigureCanvasAgg(figure)  # attaches the Agg canvas: no pyplot state
    ax = figure.add_subplot()
    bars = ax.bar(data["groups"], data["means"], yerr=data["stds"], capsize=4, color="#4C72B0")
    ax.bar_label(bars, labels=[f"{m:.1f}" for m in data["means"]], padding=3)
    ax.set_ylabel(f"{name.upper()} (%)")
    ax.set_title(f"{name.upper()} by level — {summary['method']}", pad=8)
    ax.set_ylim(*data["ylim"])
    if data["note"]:
        ax.text(0.5, 0.55, data["note"], transform=ax.transAxes, ha="center", fontsize=11)
    return figure


def charts(summary: dict[str, Any], out: Path) -> list[Path]:
    """One PNG per metric (``chart_figure``) in ``out``."""
    written = []
    for name in METRICS:
        path = out / f"{name}.png"
        chart_figure(summary, name).savefig(path)
        written.append(path)
    return written


def write_report(episodes: list[Episode], method: str, out: Path) -> dict[str, Any]:
    summary = summarize(episodes, method)
    (out / "summary.json").write_text(json.dumps(summary, indent=2), encoding="utf-8")
    (out / "summary.md").write_text(markdown(summary), encoding="utf-8")
    charts(summary, out)
    return summary
