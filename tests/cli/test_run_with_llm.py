"""``assistantx run --reasoner llm`` as a separate process against the scripted server."""

from __future__ import annotations

import asyncio
import json
import os
import sys
from typing import Any

import pytest

from assistantx.core.actions import Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import ScriptedLLM
from helpers.llm_office import CANONICAL_FETCH, decision, script_helpers

# Starts processes (a server, the CLI) or localizes on big maps: not in `make test-fast`.
pytestmark = pytest.mark.slow


async def _run_cli(env: dict[str, str], *args: str) -> tuple[int, str, str]:
    process = await asyncio.create_subprocess_exec(
        sys.executable,
        "-m",
        "assistantx",
        "run",
        *args,
        env=env,
        stdout=asyncio.subprocess.PIPE,
        stderr=asyncio.subprocess.PIPE,
    )
    # The server answers on this event loop while the command runs in its own process.
    stdout, stderr = await asyncio.wait_for(process.communicate(), timeout=60)
    assert process.returncode is not None
    return process.returncode, stdout.decode(), stderr.decode()


def _env(**values: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ASSISTANTX_")}
    env.update(values)
    return env


async def test_run_with_the_llm_reasoner_prints_the_json_summary(
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    script_helpers(scripted_llm)
    item = "stapler:zhang"
    steps: list[dict[str, Any]] = [
        decision(Inquire(contact="zhang", question="Could you lend Lee your stapler?"), Wait()),
        decision(
            Move(place="zhang"),
            SendQR(contact="zhang", item=item, purpose="deposit"),
            WaitInPlace(person="zhang"),
        ),
        decision(
            Move(place="lee"),
            SendQR(contact="lee", item=item, purpose="collect"),
            WaitInPlace(person="lee"),
        ),
        decision(Stop(outcome="done", summary="Zhang's stapler is with you.")),
    ]
    scripted_llm.script("decision", *steps)
    env = _env(
        ASSISTANTX_LLM_BASE_URL=scripted_llm.base_url,
        ASSISTANTX_LLM_MODEL="scripted-model",
        ASSISTANTX_LLM_API_KEY="sk-test",
    )
    scripted_llm.api_key = "sk-test"

    code, out, err = await _run_cli(
        env, "--as", "lee", "--reasoner", "llm", "--json", "bring me Zhang's stapler"
    )

    assert code == 0, err
    summary = json.loads(out.strip().splitlines()[-1])
    assert summary["reasoner"] == "llm"
    assert summary["outcome"] == "done"
    assert [a["type"] for a in summary["actions"]] == CANONICAL_FETCH
    assert summary["steps"] == 4
    assert summary["llm_calls"] == len(scripted_llm.requests) == 15  # 4 agents x 4, no reflect
    assert summary["prompt_tokens"] > 0 and summary["completion_tokens"] > 0
    assert all(r.status == 200 for r in scripted_llm.requests)
    # The printed trace ends with the usage line; with --json it goes to stderr, so stdout
    # holds only the JSON object.
    assert "llm: 15 calls" in err
    assert len(out.strip().splitlines()) == 1


async def test_run_with_the_llm_reasoner_needs_a_base_url() -> None:
    code, _, err = await _run_cli(_env(), "--as", "lee", "--reasoner", "llm", "hello")
    assert code == 1
    assert "ASSISTANTX_LLM_BASE_URL" in err  # errors go to stderr, one line


async def test_run_reports_a_server_that_refuses_us(
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    scripted_llm.api_key = "the-right-key"
    env = _env(ASSISTANTX_LLM_BASE_URL=scripted_llm.base_url, ASSISTANTX_LLM_API_KEY="wrong")
    code, out, err = await _run_cli(env, "--as", "lee", "--reasoner", "llm", "--json", "hello")
    assert code == 1
    summary = json.loads(out.strip().splitlines()[-1])
    assert summary["outcome"] == "failed"
    # the requester reads words; the operator's log has the status and the address
    assert summary["summary"] == (
        "I could not complete this: my language model server refused the request, so I stopped."
    )
    assert "HTTP 401" in err
    assert scripted_llm.requests[0].status == 401
