"""The OpenAI chat-completions wire format: reading answers (plain and streamed) and usage.

Servers differ in what they send: ``usage`` may be missing or ``null`` (tokens are then
estimated at four characters per token and marked ``estimated``), ``content`` may be ``null``
(a refusal, a reasoning model that spent its budget) or a list of text parts; both become plain
text. A streamed answer is gathered chunk by chunk into the shape of a plain one; with
``stream_options.include_usage`` the server sends its own counts in the last chunk.
"""

from __future__ import annotations

import json
import math
from typing import Any

import httpx

from assistantx.core.errors import LLMError
from assistantx.core.ports.model import Usage

CHARS_PER_TOKEN = 4
_ERROR_EXCERPT_CHARS = 300


def estimate_tokens(text: str) -> int:
    """A rough token count for servers that do not report usage."""
    return math.ceil(len(text) / CHARS_PER_TOKEN)


def excerpt(response: httpx.Response) -> str:
    text = response.text.strip().replace("\n", " ")
    if len(text) > _ERROR_EXCERPT_CHARS:
        return text[:_ERROR_EXCERPT_CHARS] + "…"
    return text


def content_text(message: dict[str, Any]) -> str:
    content = message.get("content")
    if isinstance(content, str):
        return content
    if isinstance(content, list):  # a list of content parts
        return "".join(
            part.get("text", "")
            for part in content
            if isinstance(part, dict) and isinstance(part.get("text"), str)
        )
    refusal = message.get("refusal")
    return refusal if isinstance(refusal, str) else ""


def _token_count(value: object) -> int | None:
    if isinstance(value, int) and not isinstance(value, bool) and value >= 0:
        return value
    return None


def usage_of(data: dict[str, Any], messages: list[dict[str, str]], text: str) -> Usage:
    reported = data.get("usage")
    prompt = completion = None
    if isinstance(reported, dict):
        prompt = _token_count(reported.get("prompt_tokens"))
        completion = _token_count(reported.get("completion_tokens"))
    if prompt is not None and completion is not None:
        return Usage(prompt_tokens=prompt, completion_tokens=completion)
    if prompt is None:
        prompt = prompt_estimate(messages)
    if completion is None:
        completion = estimate_tokens(text)
    return Usage(prompt_tokens=prompt, completion_tokens=completion, estimated=True)


def prompt_estimate(messages: list[dict[str, str]]) -> int:
    return estimate_tokens("".join(m["content"] for m in messages))


class StreamedAnswer:
    """A streamed answer as it arrives: text so far, finish reason, usage if sent."""

    def __init__(self) -> None:
        self.parts: list[str] = []
        self.finish_reason: str | None = None
        self.usage: dict[str, Any] | None = None
        self.model: str | None = None

    @property
    def text(self) -> str:
        return "".join(self.parts)

    def add(self, chunk: dict[str, Any]) -> None:
        if isinstance(chunk.get("model"), str):
            self.model = chunk["model"]
        if isinstance(chunk.get("usage"), dict):
            self.usage = chunk["usage"]
        for choice in chunk.get("choices") or []:
            if not isinstance(choice, dict) or choice.get("index", 0) != 0:
                continue
            delta = choice.get("delta")
            if isinstance(delta, dict) and isinstance(delta.get("content"), str):
                self.parts.append(delta["content"])
            if isinstance(choice.get("finish_reason"), str):
                self.finish_reason = choice["finish_reason"]

    def as_completion(self, model: str) -> dict[str, Any]:
        """The streamed answer in the shape of a non-streamed one."""
        data: dict[str, Any] = {
            "model": self.model or model,
            "choices": [
                {
                    "index": 0,
                    "message": {"role": "assistant", "content": self.text},
                    "finish_reason": self.finish_reason,
                }
            ],
        }
        if self.usage is not None:
            data["usage"] = self.usage
        return data


def parse_chunk(payload: str, endpoint: str) -> dict[str, Any]:
    """One ``data:`` line of a streamed answer, decoded."""
    try:
        chunk = json.loads(payload)
    except ValueError as exc:
        raise LLMError(f"{endpoint} streamed a chunk that is not JSON") from exc
    if not isinstance(chunk, dict):
        raise LLMError(f"{endpoint} streamed a chunk that is not an object")
    if isinstance(chunk.get("error"), dict | str):
        raise LLMError(f"{endpoint} reported an error mid-stream: {chunk['error']}")
    return chunk


def decode_answer(response: httpx.Response, endpoint: str) -> dict[str, Any]:
    """A plain answer's JSON, checked to hold a first choice with a message."""
    try:
        data = response.json()
    except ValueError as exc:
        raise LLMError(
            f"{endpoint} answered with a body that is not JSON: {excerpt(response)}"
        ) from exc
    choices = data.get("choices") if isinstance(data, dict) else None
    if not isinstance(choices, list) or not choices or not isinstance(choices[0], dict):
        raise LLMError(f"{endpoint} answered without choices: {excerpt(response)}")
    message = choices[0].get("message")
    if not isinstance(message, dict):
        raise LLMError(f"{endpoint} answered without a message: {excerpt(response)}")
    return data  # type: ignore[no-any-return]
