"""What an OpenAI-compatible server can do for us, found out by asking it.

:func:`probe_server` tries each structured-output mode with the real Decision schema (the
largest we send), then asks for every agent's output in the best mode the server accepted,
reads the context length where the server publishes it (vLLM's ``max_model_len``,
llama.cpp's ``/props`` ``n_ctx``, a ``meta``/``n_ctx`` field) and measures tokens per second
on those answers. ``assistantx llm probe`` prints the report.
"""

from __future__ import annotations

import time
from typing import Any

import httpx
from pydantic import BaseModel

from assistantx.adapters.model.openai_compat import OpenAICompatibleModel
from assistantx.core.errors import LLMError, ModelBehaviorError
from assistantx.core.ports.model import ChatRequest, Message, StructuredMode
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


def _model(base: OpenAICompatibleModel, mode: StructuredMode) -> OpenAICompatibleModel:
    return OpenAICompatibleModel(
        base.base_url,
        base.model,
        api_key=base._api_key,  # the same credentials, another mode
        timeout_s=base.timeout_s,
        max_tokens=base.max_tokens,
        structured=mode,  # type: ignore[arg-type]
        stream=base.stream,
        call_budget_s=base.call_budget_s,
    )


async def probe_server(
    base: OpenAICompatibleModel, schemas: dict[str, type[BaseModel]]
) -> dict[str, Any]:
    """A JSON-able report: modes accepted, each agent schema's result, context, tokens/s."""
    report: dict[str, Any] = {"endpoint": base.endpoint, "model": base.model, "modes": {}}
    largest = max(schemas.items(), key=lambda kv: len(str(kv[1].model_json_schema())))
    for mode in MODES:
        async with _model(base, mode) as model:
            try:
                result = await structured_call(model, _request(*largest), largest[1], max_retries=0)
            except ModelBehaviorError as exc:
                report["modes"][mode] = f"accepted, output invalid: {exc.last_error[:160]}"
            except LLMError as exc:
                report["modes"][mode] = f"refused: {str(exc)[:160]}"
            else:
                report["modes"][mode] = "accepted, output valid"
                del result
    accepted = [m for m in MODES if str(report["modes"][m]).startswith("accepted")]
    best: StructuredMode | None = accepted[0] if accepted else None
    report["best_mode"] = best
    report["enforced"] = best in ("json_schema", "json_object_schema")
    report["agents"] = {}
    tokens = 0
    seconds = 0.0
    if best is not None:
        async with _model(base, best) as model:
            for name, output_type in schemas.items():
                started = time.perf_counter()
                try:
                    result = await structured_call(
                        model, _request(name, output_type), output_type, max_retries=1
                    )
                except (LLMError, ModelBehaviorError) as exc:
                    report["agents"][name] = f"failed: {str(exc)[:160]}"
                    continue
                seconds += time.perf_counter() - started
                tokens += result.usage.completion_tokens
                report["agents"][name] = (
                    f"valid after {len(result.attempts)} attempt(s), "
                    f"{result.usage.prompt_tokens}+{result.usage.completion_tokens} tokens"
                )
    report["tokens_per_s"] = round(tokens / seconds, 1) if seconds > 0 else None
    report["context_tokens"] = await context_length(base)
    report["ok"] = best is not None and all(
        str(v).startswith("valid") for v in report["agents"].values()
    )
    return report


async def context_length(base: OpenAICompatibleModel) -> int | None:
    """The server's context length where it publishes one; None when it does not."""
    root = base.base_url.removesuffix("/v1")
    async with httpx.AsyncClient(timeout=10.0) as client:
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
