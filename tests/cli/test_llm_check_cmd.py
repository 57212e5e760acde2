"""``assistantx llm check`` against the scripted server."""

from __future__ import annotations

import asyncio
import json

import pytest

from assistantx.cli import main
from assistantx.cli.llm_cmd import check
from assistantx.core.settings import Settings
from fakes.scripted_llm import Reply, ScriptedLLM, json_reply, server_error


async def test_reports_mode_tokens_and_latency(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False
    scripted_llm.script("llm-check", json_reply({"word": "pong"}))
    report = await check(Settings(llm_base_url=scripted_llm.base_url, llm_model="tiny"))
    assert report["ok"] is True
    assert report["answer"] == "pong"
    assert report["structured_mode"] == "json_object_schema"
    assert report["model"] == "tiny"
    assert report["attempts"] == 1
    assert report["prompt_tokens"] > 0
    assert report["usage_estimated"] is False


async def test_reports_failure(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.script("llm-check", *(server_error(503) for _ in range(2)))
    report = await check(
        Settings(llm_base_url=scripted_llm.base_url, llm_max_retries=1, llm_timeout_s=1.0)
    )
    assert report["ok"] is False
    assert "HTTP 503" in report["error"]


async def test_command_exit_codes(
    scripted_llm: ScriptedLLM, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.delenv("ASSISTANTX_LLM_BASE_URL", raising=False)
    assert main(["llm", "check"]) == 2
    assert "ASSISTANTX_LLM_BASE_URL is not set" in capsys.readouterr().out

    monkeypatch.setenv("ASSISTANTX_LLM_BASE_URL", scripted_llm.base_url)
    scripted_llm.script("llm-check", Reply(content='{"word": "pong"}', usage=None))
    # The command runs its own event loop; the server keeps serving on this one.
    assert await asyncio.to_thread(main, ["llm", "check", "--json"]) == 0
    report = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert report["ok"] is True
    assert report["usage_estimated"] is True
