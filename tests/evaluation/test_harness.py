"""The eval command end to end: results, summary, charts, resume, parallel jobs, another office."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path

import pytest

import assistantx.evaluation.report as eval_report
from assistantx.adapters.model import model_from_settings
from assistantx.cli import main
from assistantx.core.office import DEFAULT_OFFICE
from assistantx.core.settings import Settings
from assistantx.evaluation.harness import EvalConfig, evaluate, load_episodes
from fakes.scripted_llm import Reply, ScriptedLLM

TASKS = DEFAULT_OFFICE.parent / "tasks.jsonl"
FIXTURES = Path(__file__).parent / "dataset" / "fixtures"


@pytest.fixture
def charts_skipped(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """For the tests of resuming, offices and jobs: the five PNG charts are a CPU-second of
    matplotlib per run and are checked by the first test below, so here they are not drawn;
    yields the folders whose charts were asked for (the command still asks)."""
    asked: list[Path] = []

    def skip(_summary: dict[str, object], out: Path) -> list[Path]:
        asked.append(out)
        return []

    monkeypatch.setattr(eval_report, "charts", skip)
    return asked


def _lines(out: Path) -> list[dict[str, object]]:
    return [json.loads(x) for x in (out / "results.jsonl").read_text().splitlines() if x]


def test_optimal_method_writes_results_summary_and_charts(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "run"
    args = ["eval", "--tasks", str(TASKS), "--method", "optimal", "--out", str(out)]
    assert main([*args, "--levels", "L2,L3", "--limit", "6", "--runs", "2"]) == 0
    episodes = _lines(out)
    assert len(episodes) == 12
    assert {e["level"] for e in episodes} <= {"L2", "L3"}
    assert all(e["trace"]["outcome"] in ("done", "unachievable") for e in episodes)
    summary = json.loads((out / "summary.json").read_text())
    everything = summary["levels"]["all"]
    assert everything["sr"]["mean"] == 1.0 and everything["rr"]["mean"] == 0.0
    assert everything["pass_k"] == {"1": 1.0, "2": 1.0}
    assert "| L2 |" in (out / "summary.md").read_text()
    for metric in ("sr", "cr", "rr", "cta", "rta"):
        assert (out / f"{metric}.png").read_bytes().startswith(b"\x89PNG")
    assert "SR" in capsys.readouterr().err  # the progress line


def test_resume_skips_finished_episodes(tmp_path: Path, charts_skipped: list[Path]) -> None:
    out = tmp_path / "run"
    args = ["eval", "--tasks", str(TASKS), "--method", "optimal", "--out", str(out), "--quiet"]
    assert main([*args, "--limit", "3"]) == 0
    first = _lines(out)
    # a cut-off last line from an interrupted run is ignored, not fatal
    with (out / "results.jsonl").open("a") as f:
        f.write('{"task_id": "t00')
    assert main([*args, "--limit", "5"]) == 0
    lines = (out / "results.jsonl").read_text().splitlines()
    done = [json.loads(x)["task_id"] for x in lines if x.endswith("}")]
    assert done[:3] == [e["task_id"] for e in first]
    assert sorted(done) == ["t001", "t002", "t003", "t004", "t005"]
    assert charts_skipped == [out, out]


def test_resume_refuses_another_method_in_the_same_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], charts_skipped: list[Path]
) -> None:
    out = tmp_path / "run"
    base = ["eval", "--tasks", str(TASKS), "--out", str(out), "--quiet", "--limit", "1"]
    assert main([*base, "--method", "optimal"]) == 0
    assert main([*base, "--method", "direct"]) == 2
    assert "holds results of optimal" in capsys.readouterr().out


@pytest.mark.slow
def test_parallel_jobs_give_the_same_scores(tmp_path: Path) -> None:
    args = ["eval", "--tasks", str(TASKS), "--method", "optimal", "--quiet", "--limit", "6"]
    assert main([*args, "--out", str(tmp_path / "a")]) == 0
    assert main([*args, "--out", str(tmp_path / "b"), "--jobs", "2"]) == 0
    a = {e["task_id"]: e["milestones"] for e in _lines(tmp_path / "a")}
    b = {e["task_id"]: e["milestones"] for e in _lines(tmp_path / "b")}
    assert a == b and len(a) == 6


def test_task_file_of_another_office_runs_unchanged(
    tmp_path: Path, charts_skipped: list[Path]
) -> None:
    out = tmp_path / "small"
    tasks = FIXTURES / "tasks.jsonl"
    # s4 has no spec, so the optimal policy cannot replay it: run the three that have one
    assert main(["eval", "--tasks", str(tasks), "--method", "optimal", "--quiet",
                 "--limit", "3", "--out", str(out)]) == 0  # fmt: skip
    episodes = {e["task_id"]: e for e in _lines(out)}
    assert set(episodes) == {"s1", "s2", "s3"}
    # Bob (the stapler owner in memory) is away; Cai, unknown to memory, answers the group
    assert [(h["item"], h["to"]) for h in episodes["s2"]["handovers"]] == [("stapler:cai", "ann")]
    assert episodes["s3"]["trace"]["outcome"] == "unachievable"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["levels"]["all"]["sr"]["mean"] == 1.0


def test_missing_spec_is_a_clear_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "small"
    tasks = FIXTURES / "tasks.jsonl"
    code = main(["eval", "--tasks", str(tasks), "--method", "optimal", "--quiet",
                 "--out", str(out)])  # fmt: skip
    assert code == 2
    assert "s4 has no 'spec'" in capsys.readouterr().out


def test_llm_baseline_without_a_model_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ASSISTANTX_LLM_BASE_URL", raising=False)
    code = main(["eval", "--tasks", str(TASKS), "--method", "react", "--quiet",
                 "--out", str(tmp_path / "r")])  # fmt: skip
    assert code == 2
    assert "ASSISTANTX_LLM_BASE_URL" in capsys.readouterr().out


def test_parallel_jobs_with_an_office_file(tmp_path: Path, charts_skipped: list[Path]) -> None:
    """``--office`` with ``--jobs 2`` once crashed: the office path is not JSON."""
    out = tmp_path / "office-jobs"
    office = DEFAULT_OFFICE
    args = ["eval", "--tasks", str(TASKS), "--office", str(office), "--method", "optimal"]
    assert main([*args, "--quiet", "--limit", "2", "--jobs", "2", "--out", str(out)]) == 0
    assert sorted(e["task_id"] for e in _lines(out)) == ["t001", "t002"]


async def test_the_settings_wall_bound_ends_an_episode(
    tmp_path: Path, scripted_llm: ScriptedLLM
) -> None:
    scripted_llm.respond_with(lambda _r: Reply(content="{}", delay_s=30))  # a stuck server
    settings = Settings(
        llm_base_url=scripted_llm.base_url,
        llm_model="slow",
        instruction_wall_s=1.0,
        llm_call_budget_s=60,
        llm_timeout_s=60,
    )
    config = EvalConfig(tasks=TASKS, out=tmp_path / "r", method="direct", limit=1)
    # the harness runs its own event loop; the scripted server keeps running on this one
    await asyncio.to_thread(evaluate, config, settings, build_model=model_from_settings)
    [episode] = load_episodes(tmp_path / "r")
    assert episode.trace.summary == "I ran out of time for this task."
    assert episode.trace.usage.llm_calls == 1  # the call cut off is counted
