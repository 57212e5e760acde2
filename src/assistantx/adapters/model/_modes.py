"""How a schema reaches the server, and falling back when the server refuses a mode.

OpenAI, vLLM, recent Ollama and llama.cpp's own server accept ``response_format: {type:
json_schema, json_schema: {name, schema, strict}}``; llama-cpp-python's server refuses it
(HTTP 500 "Input should be 'text' or 'json_object'") but enforces ``{type: json_object,
schema}`` as a grammar; older servers accept only ``{type: json_object}``. With ``auto`` the
model starts at ``json_schema`` and falls back, once per instance and remembered, to
``json_object_schema``, ``json_object`` and plain prompting as the server refuses each. The
two enforced modes send the schema only to the server (the prompt carries an outline); the
other two carry the schema in the system message (OpenAI's JSON mode also insists the word
"JSON" appears in the prompt).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Literal

from assistantx.core.ports.model import ChatRequest, StructuredMode

# Words in an error body that mean "I do not understand this response_format".
_RESPONSE_FORMAT_WORDS = ("response_format", "response format", "json_schema", "json_object")
FALLBACK_ORDER: dict[StructuredMode, StructuredMode] = {
    "json_schema": "json_object_schema",
    "json_object_schema": "json_object",
    "json_object": "prompt",
}
StructuredSetting = Literal["auto", "json_schema", "json_object_schema", "json_object", "prompt"]


@dataclass(frozen=True)
class BodyOptions:
    """What every call of one model sends besides the conversation."""

    model: str
    temperature: float
    seed: int | None
    max_tokens: int | None
    stream: bool


def schema_instruction(schema: dict[str, Any]) -> str:
    """The system-prompt text that asks for JSON when the server cannot enforce a schema."""
    return (
        "Answer with exactly one JSON object and nothing else. "
        "It must conform to this JSON schema:\n"
        f"```json\n{json.dumps(schema, separators=(',', ':'), sort_keys=True)}\n```"
    )


def schema_name(request: ChatRequest) -> str:
    # OpenAI allows [A-Za-z0-9_-]{1,64}; anything else becomes "_".
    raw = request.schema_name or f"{request.agent}_output"
    cleaned = "".join(c if c.isascii() and (c.isalnum() or c in "_-") else "_" for c in raw)
    return cleaned[:64] or "output"


def _mentions_response_format(excerpt: str) -> bool:
    lowered = excerpt.lower()
    return any(word in lowered for word in _RESPONSE_FORMAT_WORDS)


def refuses_response_format(status_code: int, excerpt: str) -> bool:
    if status_code in (400, 422):
        return _mentions_response_format(excerpt)
    # Some llama.cpp forks answer 500 "response_format type must be one of ...".
    return status_code >= 500 and "response_format" in excerpt.lower()


def with_schema_instruction(
    messages: list[dict[str, str]], schema: dict[str, Any]
) -> list[dict[str, str]]:
    instruction = schema_instruction(schema)
    if messages and messages[0]["role"] == "system":
        first = {"role": "system", "content": f"{messages[0]['content']}\n\n{instruction}"}
        return [first, *messages[1:]]
    return [{"role": "system", "content": instruction}, *messages]


def request_body(
    request: ChatRequest, mode: StructuredMode, options: BodyOptions
) -> dict[str, Any]:
    """The JSON body of one call, the schema sent the way ``mode`` says."""
    messages = [m.model_dump() for m in request.messages]
    if request.json_schema is not None and mode in ("json_object", "prompt"):
        messages = with_schema_instruction(messages, request.json_schema)
    body: dict[str, Any] = {
        "model": options.model,
        "messages": messages,
        "temperature": options.temperature,
        "stream": options.stream,
    }
    if options.stream:
        # the server's own token counts in the last chunk (OpenAI, vLLM, llama.cpp)
        body["stream_options"] = {"include_usage": True}
    if options.seed is not None:
        body["seed"] = options.seed
    if options.max_tokens is not None:
        body["max_tokens"] = options.max_tokens
    if mode == "json_schema" and request.json_schema is not None:
        body["response_format"] = {
            "type": "json_schema",
            "json_schema": {
                "name": schema_name(request),
                "schema": request.json_schema,
                "strict": request.schema_strict,
            },
        }
    elif mode == "json_object_schema" and request.json_schema is not None:
        body["response_format"] = {"type": "json_object", "schema": request.json_schema}
    elif mode == "json_object":
        body["response_format"] = {"type": "json_object"}
    return body
