"""``assistantx llm probe`` against the scripted server."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel

from assistantx.adapters.model import OpenAICompatibleModel
from assistantx.adapters.model.probe import MODES, NOT_TRIED, probe_server
from assistantx.core.trace import Decision, Percept, Plan, Reflection
from fakes.scripted_llm import Reply, ScriptedLLM
from helpers.servers import free_port

EXAMPLES: dict[str, dict[str, Any]] = {
    "Percept": {"people": ["lee"], "summary": "lee wants a stapler"},
    "Plan": {"goal": "a stapler for lee", "subgoals": [{"description": "ask zhang"}]},
    "Decision": {"actions": [{"type": "wait", "timeout_s": 60}]},
    "Reflection": {"verdict": "Y", "reason": "fine"},
}


async def test_probe_reports_modes_every_agent_schema_and_speed(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.supports_json_schema = False  # like llama-cpp-python's server
    by_agent = {
        "probe-perception": EXAMPLES["Percept"],
        "probe-planning": EXAMPLES["Plan"],
        "probe-decision": EXAMPLES["Decision"],
        "probe-reflection": EXAMPLES["Reflection"],
    }
    for agent, example in by_agent.items():
        scripted_llm.respond_with(lambda _r, e=example: e, agent)  # type: ignore[misc]
    base = OpenAICompatibleModel(scripted_llm.base_url, "tiny", max_tokens=64)
    schemas = {
        "perception": Percept,
        "planning": Plan,
        "decision": Decision,
        "reflection": Reflection,
    }
    report = await probe_server(base, schemas)

    assert report["modes"]["json_schema"].startswith("unsupported: the server refused")
    assert report["modes"]["json_object_schema"] == "accepted, output valid"
    assert report["best_mode"] == "json_object_schema"
    assert report["enforced"] is True
    assert sorted(report["agents"]) == sorted(schemas)
    assert all(v.startswith("valid after 1 attempt") for v in report["agents"].values())
    assert report["tokens_per_s"] is not None and report["tokens_per_s"] > 0
    assert report["ok"] is True
    assert report["verdict"] == "usable: json_object_schema (enforced by the server)"
    # every agent's own schema went to the server, not a toy one
    sent = {
        r.agent: r.response_format
        for r in scripted_llm.requests
        if r.response_format and r.response_format.get("schema")
    }
    assert "probe-reflection" in sent and "probe-perception" in sent


SCHEMAS: dict[str, type[BaseModel]] = {"perception": Percept, "decision": Decision}


async def test_a_refused_connection_is_reported_as_unreachable_after_one_request() -> None:
    base = OpenAICompatibleModel(f"http://127.0.0.1:{free_port()}/v1", "none")
    report = await probe_server(base, SCHEMAS, budget_s=30)

    assert report["modes"]["json_schema"].startswith("refused: no connection")
    assert {report["modes"][m] for m in MODES[1:]} == {"not tried: unreachable"}
    assert report["best_mode"] is None and report["ok"] is False
    assert report["verdict"].startswith("unreachable")
    assert report["context_tokens"] is None


async def test_a_timeout_is_told_apart_and_the_budget_is_kept(scripted_llm: ScriptedLLM) -> None:
    scripted_llm.respond_with(lambda _r: Reply(content="{}", delay_s=30))
    base = OpenAICompatibleModel(scripted_llm.base_url, "slow", call_budget_s=0.3)
    report = await probe_server(base, SCHEMAS, budget_s=0.9)

    # every call waits its 0.3 s out, so at most three fit in 0.9 s: the last mode is left
    modes = [report["modes"][m] for m in MODES]
    assert modes[0].startswith("timed out (")
    timed_out = [m for m in modes if m.startswith("timed out")]
    assert modes[len(timed_out) :] == [NOT_TRIED] * (len(MODES) - len(timed_out))
    assert modes[-1] == NOT_TRIED
    assert len(scripted_llm.requests) == len(timed_out)  # one request per mode, no retries
    assert report["verdict"].startswith("too slow")
    assert report["budget_s"] == 0.9


async def test_a_server_that_refuses_every_format_is_unsupported(
    scripted_llm: ScriptedLLM,
) -> None:
    scripted_llm.supports_json_schema = False
    scripted_llm.supports_json_object = False
    scripted_llm.respond_with(lambda _r: Reply(content="no JSON from me"))
    base = OpenAICompatibleModel(scripted_llm.base_url, "plain")
    report = await probe_server(base, SCHEMAS, budget_s=30)

    assert report["modes"]["json_schema"].startswith("unsupported")
    assert report["modes"]["json_object"].startswith("unsupported")
    assert report["modes"]["prompt"].startswith("accepted, output invalid")
