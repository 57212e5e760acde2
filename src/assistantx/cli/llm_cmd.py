"""``assistantx llm check``: does the configured model server answer, and how?
``assistantx llm probe``: which structured-output modes it accepts, whether every agent's
schema comes back valid, its context length and tokens per second.

Sends one small structured request to ``ASSISTANTX_LLM_BASE_URL`` with the configured model
and key, and reports the answer, the latency, the token usage (reported or estimated) and the
structured-output mode the server accepted (json_schema, json_object or plain prompting).
Exit codes: 0 answered correctly, 1 the server or the model failed, 2 no LLM configured.
"""

from __future__ import annotations

import argparse
import asyncio
import json
from typing import Any

from pydantic import BaseModel, ValidationError

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, structured_call
from assistantx.core.errors import LLMError, ModelBehaviorError
from assistantx.core.settings import Settings


class _Echo(BaseModel):
    word: str


_PROMPT = (
    "AGENT: llm-check\nYou are checking that a connection works. "
    'Answer with the JSON object {"word": "pong"} and nothing else.'
)


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    llm = sub.add_parser("llm", help="inspect the configured language model server")
    llm_sub = llm.add_subparsers(dest="llm_command", required=True, metavar="ACTION")
    check = llm_sub.add_parser("check", help="send one structured request and report")
    check.add_argument("--json", action="store_true", help="print the report as one JSON line")
    check.set_defaults(func=_check)
    probe = llm_sub.add_parser(
        "probe", help="try every structured-output mode and every agent schema; report"
    )
    probe.add_argument("--json", action="store_true", help="print the report as one JSON line")
    probe.add_argument(
        "--budget-s",
        type=float,
        default=300.0,
        help="wall time for the whole probe (each call also keeps to ASSISTANTX_LLM_CALL_BUDGET_S)",
    )
    probe.set_defaults(func=_probe)


def _llm_settings() -> Settings | None:
    """The settings, when they are valid and name an LLM server; else None, said in one line."""
    try:
        settings = Settings()
    except ValidationError as exc:
        print(f"error: bad ASSISTANTX_* settings: {exc}")
        return None
    if not settings.llm_enabled:
        print("error: ASSISTANTX_LLM_BASE_URL is not set; the LLM reasoner is off")
        return None
    return settings


def _probe(args: argparse.Namespace) -> int:
    settings = _llm_settings()
    if settings is None:
        return 2
    from assistantx.adapters.model.probe import probe_server
    from assistantx.core.trace import Decision, Percept, Plan, Reflection

    schemas: dict[str, type[BaseModel]] = {
        "perception": Percept,
        "planning": Plan,
        "decision": Decision,
        "reflection": Reflection,
    }
    base = OpenAICompatibleModel.from_settings(settings)
    report = asyncio.run(probe_server(base, schemas, budget_s=args.budget_s))
    report["context_setting"] = settings.llm_context_tokens
    if args.json:
        print(json.dumps(report))
    else:
        for key, value in report.items():
            if isinstance(value, dict):
                print(f"{key}:")
                for inner, text in value.items():
                    print(f"  {inner}: {text}")
            else:
                print(f"{key}: {value}")
    return 0 if report["ok"] else 1


def _check(args: argparse.Namespace) -> int:
    settings = _llm_settings()
    if settings is None:
        return 2
    report = asyncio.run(check(settings))
    if args.json:
        print(json.dumps(report))
    else:
        for key, value in report.items():
            print(f"{key}: {value}")
    return 0 if report["ok"] else 1


async def check(settings: Settings) -> dict[str, Any]:
    """Ask the configured server for one tiny structured answer; a JSON-able report."""
    model = OpenAICompatibleModel.from_settings(settings)
    report: dict[str, Any] = {"ok": False, "endpoint": model.endpoint, "model": model.model}
    request = ChatRequest(
        messages=(Message(role="system", content=_PROMPT), Message(role="user", content="ping")),
        agent="llm-check",
    )
    async with model:
        try:
            result = await structured_call(
                model, request, _Echo, max_retries=settings.llm_output_retries
            )
        except (LLMError, ModelBehaviorError) as exc:
            report["error"] = str(exc)
            report["structured_mode"] = model.structured_mode
            return report
    last = result.attempts[-1].response
    report.update(
        ok=True,
        answer=result.output.word,
        served_by=last.model,
        structured_mode=last.structured_mode,
        latency_s=round(result.latency_s, 3),
        prompt_tokens=result.usage.prompt_tokens,
        completion_tokens=result.usage.completion_tokens,
        usage_estimated=result.usage.estimated,
        attempts=len(result.attempts),
        transport_retries=sum(a.response.retries for a in result.attempts),
    )
    return report
