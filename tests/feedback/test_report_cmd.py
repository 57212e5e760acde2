"""``assistantx report`` on a journal written by a real instruction and survey."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from assistantx.cli import main
from assistantx.core.actions import Move, Stop
from assistantx.core.office import Office

from .scripted import harness


async def test_report_command_writes_json_markdown_and_charts(
    office: Office, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    data = tmp_path / "data"
    async with harness(office, data / "journal.sqlite3") as h:
        await h.run(
            "lee", "fetch my book", [[Move(place="yang")], [Stop(outcome="done", summary="ok")]]
        )
        await h.say("lee", "all no")
    out = tmp_path / "out"
    code = main(["report", "--data-dir", str(data), "--out", str(out), "--json"])
    assert code == 0
    lines = capsys.readouterr().out.strip().splitlines()
    report = json.loads(lines[-1])
    assert report["instructions"]["by_outcome"]["done"] == 1
    assert report["surveys"]["questions"][0]["answers"]["no"] == {"count": 1, "share": 1.0}
    assert sorted(p.name for p in out.iterdir()) == [
        "usage-outcomes.png",
        "usage-survey.png",
        "usage-walking.png",
        "usage.json",
        "usage.md",
    ]
    assert json.loads((out / "usage.json").read_text()) == report
    assert (out / "usage-walking.png").read_bytes().startswith(b"\x89PNG")
    assert "# Usage report" in (out / "usage.md").read_text()

    # Instructions before the period are left out (sim time starts at 0 s since the epoch).
    code = main(
        ["report", "--data-dir", str(data), "--out", str(out), "--from", "1971-01-01", "--json"]
    )
    assert code == 0
    assert (
        json.loads(capsys.readouterr().out.strip().splitlines()[-1])["instructions"]["total"] == 0
    )


def test_report_command_rejects_bad_input(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["report", "--data-dir", str(tmp_path), "--from", "soon"]) == 2
    assert "is not a time" in capsys.readouterr().out
    assert main(["report", "--data-dir", str(tmp_path / "none")]) == 2
    assert "no journal" in capsys.readouterr().out
    (tmp_path / "journal.sqlite3").write_bytes(b"not a database at all" * 100)
    assert main(["report", "--data-dir", str(tmp_path)]) == 2
    assert "error:" in capsys.readouterr().out
