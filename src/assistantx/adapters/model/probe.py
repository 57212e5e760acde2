"""What an OpenAI-compatible server can do for us, found out by asking it.

:func:`probe_server` tries each structured-output mode with the real Decision schema (the
largest we send), then asks for every agent's output in the best mode the server accepted,
reads the context length where the server publishes it (vLLM's ``max_model_len``,
llama.cpp's ``/props`` ``n_ctx``, a ``meta``/``n_ctx`` field) and measures tokens per second
on those answers. Each finding is one request (no retries), and the whole probe keeps to a
stated budget; a refused connection, a timeout and a refused response_format are reported as
what they are. ``assistantx llm probe`` prints the report.
"""

from __future__ import annotations

import time
from typing import Any

import httpx
from pydantic import BaseModel

from assistantx.adapters.model.openai_compat import OpenAICompatibleModel
from assistantx.core.errors import LLMError, ModelBehaviorError
from assistantx.core.http_retry import RetryPolicy
from assistantx.core.ports.model import ChatRequest, LLMCallFailed, Message, StructuredMode
from assistantx.core.structured.call import structured_call
from assistantx.core.structured.schema import grammar_schema, schema_outline

MODES: tuple[StructuredMode, ...] = ("json_schema", "json_object_schema", "json_object", "prompt")
_PROMPT = (
    "You are testing a connection. Answer with one small, valid JSON object of this shape "
    "(short strings, at most one list element):\n{outline}"
)


def _request(name: str, model: type[BaseModel]) -> ChatRequest:
    return ChatRequest(
        messages=(
            Message(role="system", content=_PROMPT.format(outline=schema_outline(model))),
            Message(role="user", content="Give the example now."),
        ),
        agent=f"probe-{name}",
        json_schema=grammar_schema(model),
        schema_name=model.__name__,
    )


def _model(
    base: OpenAICompatibleModel, mode: StructuredMode, budget_s: float
) -> OpenAICompatibleModel:
    return OpenAICompatibleModel(
        base.base_url,
        base.model,
        api_key=base._api_key,  # the same credentials, another mode
        timeout_s=min(base.timeout_s, budget_s),
        max_tokens=base.max_tokens,
        structured=mode,  # type: ignore[arg-type]
        stream=base.stream,
        call_budget_s=budget_s,
        retry=RetryPolicy(max_retries=0),  # one request per question: the answer is the finding
    )


class _Budget:
    """The probe's wall time, shared by its calls: each call gets what is left, capped."""

    def __init__(self, total_s: float, per_call_s: float | None) -> None:
        self.total_s = total_s
        self.per_call_s = per_call_s
        self._ends = time.monotonic() + total_s

    def left_s(self) -> float:
        return self._ends - time.monotonic()

    def for_call(self) -> float | None:
        """The next call's budget; None when too little is left to try."""
        left = self.left_s()
        if left < _MIN_CALL_S:
            return None
        return min(left, self.per_call_s) if self.per_call_s else left


_MIN_CALL_S = 0.05
NOT_TRIED = "not tried: the probe's budget was spent"


def _failure(exc: LLMError) -> str:
    """A failed call in words that tell its cause apart."""
    if isinstance(exc, LLMCallFailed):
        words = {
            "refused": "refused: no connection",
            "timed_out": "timed out",
            "unsupported": "unsupported: the server refused this response_format",
            "rejected": "rejected",
            "server_error": "server error",
            "broken": "connection broke off",
        }[exc.kind]
        return f"{words} ({str(exc)[:140]})"
    return f"failed ({str(exc)[:140]})"


async def probe_server(
    base: OpenAICompatibleModel,
    schemas: dict[str, type[BaseModel]],
    *,
    budget_s: float = 300.0,
) -> dict[str, Any]:
    """A JSON-able report: modes accepted, each agent schema's result, context, tokens/s, and
    a ``verdict`` that tells an unreachable server, a slow one and one that supports no
    structured mode apart; the whole probe takes at most about ``budget_s`` seconds (each
    call at most the model's own call budget)."""
    budget = _Budget(budget_s, base.call_budget_s)
    report: dict[str, Any] = {
        "endpoint": base.endpoint,
        "model": base.model,
        "budget_s": budget_s,
        "modes": {},
    }
    largest = max(schemas.items(), key=lambda kv: len(str(kv[1].model_json_schema())))
    kinds: list[str] = []
    for mode in MODES:
        call_s = budget.for_call()
        if call_s is None or "refused" in kinds:  # nobody listens: the other modes cannot tell
            report["modes"][mode] = NOT_TRIED if call_s is None else "not tried: unreachable"
            continue
        async with _model(base, mode, call_s) as model:
            try:
                await structured_call(model, _request(*largest), largest[1], max_retries=0)
            except ModelBehaviorError as exc:
                report["modes"][mode] = f"accepted, output invalid: {exc.last_error[:160]}"
            except LLMError as exc:
                report["modes"][mode] = _failure(exc)
                kinds.append(exc.kind if isinstance(exc, LLMCallFailed) else "failed")
            else:
                report["modes"][mode] = "accepted, output valid"
    accepted = [m for m in MODES if str(report["modes"][m]).startswith("accepted")]
    best: StructuredMode | None = accepted[0] if accepted else None
    report["best_mode"] = best
    report["enforced"] = best in ("json_schema", "json_object_schema")
    report["agents"] = {}
    tokens = 0
    seconds = 0.0
    if best is not None:
        for name, output_type in schemas.items():
            call_s = budget.for_call()
            if call_s is None:
                report["agents"][name] = NOT_TRIED
                continue
            started = time.perf_counter()
            async with _model(base, best, call_s) as model:
                try:
                    result = await structured_call(
                        model, _request(name, output_type), output_type, max_retries=1
                    )
                except (LLMError, ModelBehaviorError) as exc:
                    report["agents"][name] = (
                        _failure(exc) if isinstance(exc, LLMError) else f"invalid: {exc}"[:160]
                    )
                    continue
            seconds += time.perf_counter() - started
            tokens += result.usage.completion_tokens
            report["agents"][name] = (
                f"valid after {len(result.attempts)} attempt(s), "
                f"{result.usage.prompt_tokens}+{result.usage.completion_tokens} tokens"
            )
    report["tokens_per_s"] = round(tokens / seconds, 1) if seconds > 0 else None
    report["context_tokens"] = (
        await context_length(base, timeout_s=min(10.0, max(budget.left_s(), 1.0)))
        if "refused" not in kinds
        else None
    )
    report["verdict"] = _verdict(best, kinds, report)
    report["ok"] = best is not None and all(
        str(v).startswith("valid") for v in report["agents"].values()
    )
    return report


def _verdict(best: StructuredMode | None, kinds: list[str], report: dict[str, Any]) -> str:
    if best is not None:
        return f"usable: {best}" + (" (enforced by the server)" if report["enforced"] else "")
    if "refused" in kinds:
        return "unreachable: nothing accepts connections at the endpoint"
    if "timed_out" in kinds:
        return "too slow: no answer within the budget; raise ASSISTANTX_LLM_CALL_BUDGET_S"
    if any(str(v) == NOT_TRIED for v in report["modes"].values()):
        return "undecided: the probe's budget ran out"
    if kinds and all(k == "unsupported" for k in kinds):
        return "unsupported: the server refused every structured-output mode"
    return "failing: " + ", ".join(sorted(set(kinds)))


async def context_length(base: OpenAICompatibleModel, *, timeout_s: float = 10.0) -> int | None:
    """The server's context length where it publishes one; None when it does not."""
    root = base.base_url.removesuffix("/v1")
    async with httpx.AsyncClient(timeout=timeout_s) as client:
        for url in (f"{base.base_url}/models", f"{root}/props"):
            try:
                response = await client.get(url)
                data = response.json() if response.is_success else None
            except (httpx.HTTPError, ValueError):
                continue
            found = _find_context(data)
            if found is not None:
                return found
    return None


def _find_context(data: Any) -> int | None:
    keys = ("max_model_len", "n_ctx", "n_ctx_train", "context_length", "context_window")
    if isinstance(data, dict):
        for key in keys:
            value = data.get(key)
            if isinstance(value, int) and not isinstance(value, bool) and value > 0:
                return value
        for value in data.values():
            found = _find_context(value)
            if found is not None:
                return found
    if isinstance(data, list):
        for value in data:
            found = _find_context(value)
            if found is not None:
                return found
    return None
