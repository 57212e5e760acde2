"""``assistantx run`` with the symbolic reasoner: the default when no LLM is configured."""

from __future__ import annotations

import json

import pytest

from assistantx.cli import main


def _last_json(out: str) -> dict[str, object]:
    data: dict[str, object] = json.loads(out.strip().splitlines()[-1])
    return data


def test_run_defaults_to_symbolic_and_finishes(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ASSISTANTX_LLM_BASE_URL", raising=False)
    monkeypatch.delenv("ASSISTANTX_REASONER", raising=False)
    code = main(["run", "--as", "lee", "--json", "bring me a stapler"])
    out, err = capsys.readouterr()
    assert code == 0
    summary = _last_json(out)
    assert summary["reasoner"] == "symbolic"
    assert summary["outcome"] == "done"
    # With --json the readable trace goes to stderr: stdout is the JSON object alone.
    assert "reflection Y" in err and "plan: bring a stapler to Lee Ming" in err


def test_run_asks_the_group_when_known_owners_are_away(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code = main(
        [
            "run",
            "--as",
            "lee",
            "--unavailable",
            "zhang,wang,hu,gao",
            "--json",
            "--quiet",
            "bring me a stapler",
        ]
    )
    summary = _last_json(capsys.readouterr().out)
    assert code == 0
    assert summary["outcome"] == "unachievable"
    actions = summary["actions"]
    assert isinstance(actions, list)
    assert any(a["type"] == "inquire" and a["contact"] == "office_work" for a in actions)
