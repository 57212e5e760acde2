"""What the usage report's charts and the evaluation's charts show: whole-instruction ticks,
legends beside the bars, people by name, an RR chart that is never an empty box; and where
``report`` and ``map render`` write by default (the data folder, not the working tree)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from assistantx.evaluation.report import chart_data
from assistantx.evaluation.report import chart_figure as chart_figure_of_evaluation
from assistantx.feedback.impact import InstructionRecord
from assistantx.feedback.report import Period, build_report, chart_figure, render_markdown
from assistantx.feedback.walking import WalkingEstimate

if TYPE_CHECKING:  # matplotlib is imported where a chart is drawn, not at collection
    from matplotlib.figure import Figure

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
NAMES = {"lee": "Dr. Lee", "hu": "Ms. Hu"}


def _record(n: int, requester: str, outcome: str) -> InstructionRecord:
    saved = 12.5 if outcome == "done" else 0.0
    return InstructionRecord(
        instruction_id=f"i{n}",
        requester=requester,
        text="bring me a stapler",
        kind="delivery",
        outcome=outcome,  # type: ignore[arg-type]
        started_at=0.0,
        ended_at=60.0,
        steps=3,
        actions=5,
        group_requests=0,
        walking=WalkingEstimate(
            instruction_id=f"i{n}",
            requester=requester,
            route=[],
            walk_m=12.5,
            robot_m=20.0,
            saved_m=saved,
            method="map",
        ),
    )


def _report() -> object:
    records = [_record(1, "lee", "done"), _record(2, "hu", "done"), _record(3, "lee", "failed")]
    return build_report(records, [], Period(start=None, end=None), names=NAMES)


def _draw(figure: Figure) -> None:
    assert figure.canvas is not None
    figure.canvas.draw()  # type: ignore[no-untyped-call]


def test_outcome_ticks_are_whole_instructions_and_the_legend_is_beside_the_bars() -> None:
    figure = chart_figure(_report(), "outcomes")  # type: ignore[arg-type]
    _draw(figure)
    axes = figure.axes[0]
    ticks = [t for t in axes.get_yticks() if axes.get_ylim()[0] <= t <= axes.get_ylim()[1]]
    assert ticks and all(float(t).is_integer() for t in ticks), ticks
    legend = axes.get_legend()
    assert legend is not None
    renderer = figure.canvas.get_renderer()  # type: ignore[attr-defined]
    box = legend.get_window_extent(renderer)
    plot = axes.get_window_extent(renderer)
    assert box.x0 >= plot.x1, (box, plot)  # right of the plot area, over no bar


def test_walking_chart_and_markdown_name_people() -> None:
    report = _report()
    figure = chart_figure(report, "walking")  # type: ignore[arg-type]
    _draw(figure)
    labels = [t.get_text() for t in figure.axes[0].get_xticklabels()]
    assert labels == ["Ms. Hu", "Dr. Lee"]
    markdown = render_markdown(report)  # type: ignore[arg-type]
    assert "| Dr. Lee | 2 | 12.5 |" in markdown
    assert "| lee |" not in markdown


def _level(rr: float) -> dict[str, object]:
    cell = {"mean": rr, "std": 0.0}
    return {m: cell for m in ("sr", "cr", "rr", "cta", "rta")}


def test_an_all_zero_rr_chart_says_so_and_keeps_a_readable_scale() -> None:
    summary = {"method": "ppdr", "levels": {"L1": _level(0.0), "L2": _level(0.0)}}
    data = chart_data(summary, "rr")
    assert data["note"] == "0 redundant actions at every level"
    assert 0 < data["ylim"][1] < 100  # RR is small: no 0..100 box with nothing in it
    some = chart_data({"method": "ppdr", "levels": {"L1": _level(0.25)}}, "rr")
    assert some["note"] is None and some["means"] == [25.0]
    assert chart_data(summary, "sr")["ylim"][1] >= 100


def _cli(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env["ASSISTANTX_DATA_DIR"] = str(cwd / "data")
    return subprocess.run(
        [sys.executable, "-m", "assistantx", *args],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_map_render_writes_under_the_data_folder_by_default(tmp_path: Path) -> None:
    work = tmp_path / "work"
    work.mkdir()
    out = _cli(work, "map", "render", "--path", "desk_03,print_room")
    assert out.returncode == 0, out.stdout + out.stderr
    written = work / "data" / "maps" / "office-desk_03-print_room.png"
    assert written.read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in work.iterdir()) == ["data"]


def test_report_writes_under_the_data_folder_by_default(tmp_path: Path) -> None:
    from assistantx.feedback.store import FeedbackStore

    work = tmp_path / "work"
    (work / "data").mkdir(parents=True)
    FeedbackStore.open(work / "data" / "journal.sqlite3").close()
    out = _cli(work, "report", "--json")
    assert out.returncode == 0, out.stdout + out.stderr
    assert json.loads(out.stdout.strip().splitlines()[-1])["instructions"]["total"] == 0
    assert (work / "data" / "report" / "usage.md").is_file()
    assert sorted(p.name for p in work.iterdir()) == ["data"]


def test_evaluation_value_labels_stay_below_the_chart_title() -> None:
    summary = {"method": "ppdr (symbolic)", "levels": {g: _level(1.0) for g in ("L1", "L2", "all")}}
    for name in ("sr", "cr", "cta", "rta"):
        figure = chart_figure_of_evaluation(summary, name)
        _draw(figure)
        renderer = figure.canvas.get_renderer()  # type: ignore[attr-defined]
        axes = figure.axes[0]
        title = axes.title.get_window_extent(renderer)
        labels = [t for t in axes.texts if t.get_text() == "100.0"]
        assert len(labels) == 3, [t.get_text() for t in axes.texts]
        for label in labels:
            box = label.get_window_extent(renderer)
            assert box.y1 <= title.y0, (name, box, title)  # under the title, not across it
