"""The one interface agents use to talk to a language model.

Agents build a :class:`ChatRequest`, hand it to a :class:`ChatModel` and get a
:class:`ChatResponse` back; they never import a provider. A provider (the OpenAI-compatible
HTTP client, the embedded local model, a test fake) subclasses :class:`ChatModel` and
implements :meth:`ChatModel._complete`. Start and stop are idempotent and happen through
``async with`` (or the app lifespan's exit stack). ``complete`` on a model that is not
started is a programming error and raises ``RuntimeError``: starting lazily would leave
connection pools that nobody closes.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from assistantx.core.errors import LLMError
from assistantx.core.lifecycle import Component

Role = Literal["system", "user", "assistant"]


class Message(BaseModel):
    model_config = ConfigDict(frozen=True)

    role: Role
    content: str


class ChatRequest(BaseModel):
    """One chat-completion call.

    ``agent`` names the caller (perception, planning, decision, reflection or a baseline's
    name); with ``instruction_id``, ``step`` and ``attempt`` it is bookkeeping for the usage
    ledger and the trace and is not part of the prompt. ``json_schema`` asks for structured
    output; the provider sends it the best way the server accepts.
    """

    model_config = ConfigDict(frozen=True)

    messages: tuple[Message, ...] = Field(min_length=1)
    agent: str = Field(min_length=1)
    json_schema: dict[str, Any] | None = None
    schema_name: str | None = None
    schema_strict: bool = Field(
        default=False,
        description="ask the server to enforce the schema exactly (OpenAI strict mode needs "
        "additionalProperties false and every property required)",
    )
    instruction_id: str | None = None
    step: int | None = None
    attempt: int = Field(default=0, ge=0, description="0, or the n-th repair of invalid output")

    def followed_by(self, *messages: Message) -> ChatRequest:
        """The same request with ``messages`` appended to the conversation."""
        return self.model_copy(update={"messages": (*self.messages, *messages)})


class Usage(BaseModel):
    """Token counts of one call, or of several added up.

    ``estimated`` is true when the server did not report them and they were estimated from
    the text length (about four characters per token).
    """

    model_config = ConfigDict(frozen=True)

    prompt_tokens: int = Field(default=0, ge=0)
    completion_tokens: int = Field(default=0, ge=0)
    estimated: bool = False

    @property
    def total_tokens(self) -> int:
        return self.prompt_tokens + self.completion_tokens

    def __add__(self, other: Usage) -> Usage:
        return Usage(
            prompt_tokens=self.prompt_tokens + other.prompt_tokens,
            completion_tokens=self.completion_tokens + other.completion_tokens,
            estimated=self.estimated or other.estimated,
        )


# How a schema reached the server: ``json_schema`` (OpenAI's response_format, vLLM, Ollama),
# ``json_object_schema`` (llama.cpp's ``{type: json_object, schema}``), ``json_object`` (JSON
# mode, schema in the prompt) or ``prompt`` (schema in the prompt only). The first two are
# enforced by the server; the prompt then carries only an outline of the shape.
StructuredMode = Literal["none", "json_schema", "json_object_schema", "json_object", "prompt"]
ENFORCED_MODES: frozenset[StructuredMode] = frozenset({"json_schema", "json_object_schema"})

# Why a call got no answer: no connection at all (``refused``), no answer in time
# (``timed_out``), the server does not accept the answer format asked for (``unsupported``),
# it refused the request (``rejected``, a 4xx), kept failing (``server_error``, 5xx or 429),
# or the connection broke off (``broken``).
FailureKind = Literal["refused", "timed_out", "unsupported", "rejected", "server_error", "broken"]


class ChatResponse(BaseModel):
    """What the model answered, and what it cost.

    ``retries`` counts transport retries (429, 5xx, timeouts) behind this one answer;
    ``structured_mode`` says how a requested schema was conveyed to the server.
    """

    model_config = ConfigDict(frozen=True)

    text: str
    usage: Usage
    latency_s: float = Field(ge=0.0)
    model: str
    finish_reason: str | None = None
    retries: int = Field(default=0, ge=0)
    structured_mode: StructuredMode = "none"


class LLMCallFailed(LLMError):
    """A call that got no usable answer (timeout, dropped connection, server error, output
    cut at ``max_tokens``), with what it cost anyway: the server read the prompt and may have
    generated tokens before it failed, and the trace must count them.

    ``user_text`` is the cause in words a requester can read (no URL, no status code).
    """

    def __init__(
        self,
        message: str,
        *,
        user_text: str,
        usage: Usage,
        latency_s: float,
        model: str,
        retries: int = 0,
        kind: FailureKind = "broken",
    ) -> None:
        super().__init__(message)
        self.kind = kind
        self.user_text = user_text
        self.usage = usage
        self.latency_s = latency_s
        self.model = model
        self.retries = retries
        # filled by structured_call: the earlier (rejected) attempts of the same agent call
        self.attempts: tuple[object, ...] = ()


class ChatModel(Component, ABC):
    """A chat model, started and stopped as a ``Component`` (``async with`` it); providers
    acquire their connection pool or process in ``_start`` and release it in ``_stop``."""

    async def complete(self, request: ChatRequest) -> ChatResponse:
        """Answer one request; provider failures surface as ``LLMError``."""
        if not self._started:
            raise RuntimeError(f"{type(self).__name__} is not started; use 'async with'")
        return await self._complete(request)

    @abstractmethod
    async def _complete(self, request: ChatRequest) -> ChatResponse:
        """Provider-specific completion of one request."""
