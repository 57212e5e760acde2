"""``assistantx llm probe`` against the scripted server."""

from __future__ import annotations

from typing import Any

from assistantx.adapters.model import OpenAICompatibleModel
from assistantx.adapters.model.probe import probe_server
from assistantx.core.trace import Decision, Percept, Plan, Reflection
from fakes.scripted_llm import ScriptedLLM

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

    assert report["modes"]["json_schema"].startswith("refused")
    assert report["modes"]["json_object_schema"] == "accepted, output valid"
    assert report["best_mode"] == "json_object_schema"
    assert report["enforced"] is True
    assert sorted(report["agents"]) == sorted(schemas)
    assert all(v.startswith("valid after 1 attempt") for v in report["agents"].values())
    assert report["tokens_per_s"] is not None and report["tokens_per_s"] > 0
    assert report["ok"] is True
    # every agent's own schema went to the server, not a toy one
    sent = {
        r.agent: r.response_format
        for r in scripted_llm.requests
        if r.response_format and r.response_format.get("schema")
    }
    assert "probe-reflection" in sent and "probe-perception" in sent
