"""A chat model on any OpenAI-compatible ``/chat/completions`` endpoint.

Tested against the protocol as OpenAI, vLLM, Ollama (``/v1``) and llama.cpp's server speak
it. Where they differ:

* Structured output. OpenAI, vLLM, recent Ollama and llama.cpp's own server accept
  ``response_format: {type: json_schema, json_schema: {name, schema, strict}}``;
  llama-cpp-python's server refuses it (HTTP 500 "Input should be 'text' or 'json_object'")
  but enforces ``{type: json_object, schema}`` as a grammar; older servers accept only
  ``{type: json_object}``. With ``structured="auto"`` the model starts at ``json_schema`` and
  falls back, once per instance and remembered, to ``json_object_schema``, ``json_object``
  and plain prompting as the server refuses each; a fixed mode never falls back. The two
  enforced modes send the schema only to the server (the prompt carries an outline); the
  other two carry the schema in the system message (OpenAI's JSON mode also insists the word
  "JSON" appears in the prompt).
* Cost. ``max_tokens`` caps each completion; ``call_budget_s`` bounds one call's wall time.
  With ``stream=True`` the answer is streamed, so a call that runs out of time closes the
  connection and the server stops generating for nobody (llama.cpp and vLLM do); a server
  that answers a streamed request with plain JSON is read as plain JSON.
* ``usage``. Some servers omit it or send ``null``; tokens are then estimated at four
  characters per token and the usage is marked ``estimated``.
* ``content`` may be ``null`` (a refusal, a reasoning model that spent its budget) or a list
  of text parts; both become plain text.

Transport failures (429, 5xx, timeouts, dropped connections) are retried with seeded
exponential backoff and jitter, honouring ``Retry-After`` up to a cap, except a timeout
against a server on this machine: it is busy with our own earlier work, and a retry would
queue behind it. After the last try an ``LLMCallFailed`` carries the cause, the cost
(prompt tokens estimated, what was streamed so far) and a cause in plain words. The API key
goes out as a bearer token and is never logged; prompt and completion bodies are logged at
DEBUG only, and not at all with ``log_bodies=False``.
"""

from __future__ import annotations

import asyncio
import json
import logging
import math
import time
from typing import TYPE_CHECKING, Any, Literal

import httpx
from pydantic import SecretStr

from assistantx.adapters.model._retry import RetryPolicy, is_retryable_status, parse_retry_after
from assistantx.core.errors import LLMError
from assistantx.core.ports.model import (
    ENFORCED_MODES,
    ChatModel,
    ChatRequest,
    ChatResponse,
    LLMCallFailed,
    StructuredMode,
    Usage,
)

if TYPE_CHECKING:
    from assistantx.core.settings import Settings

logger = logging.getLogger(__name__)

AGENT_HEADER = "X-AssistantX-Agent"
CHARS_PER_TOKEN = 4
_ERROR_EXCERPT_CHARS = 300
# Words in an error body that mean "I do not understand this response_format".
_RESPONSE_FORMAT_WORDS = ("response_format", "response format", "json_schema", "json_object")
_FALLBACK_ORDER: dict[StructuredMode, StructuredMode] = {
    "json_schema": "json_object_schema",
    "json_object_schema": "json_object",
    "json_object": "prompt",
}
StructuredSetting = Literal["auto", "json_schema", "json_object_schema", "json_object", "prompt"]
_LOCAL_HOSTS = frozenset({"127.0.0.1", "localhost", "::1", "0.0.0.0", "[::1]"})


def is_local_url(url: str) -> bool:
    """True for a server on this machine (whose timeouts are not worth retrying)."""
    host = httpx.URL(url).host
    return host in _LOCAL_HOSTS or host.startswith("127.")


class _ResponseFormatRejected(Exception):
    """The server refused the ``response_format`` we sent (internal signal)."""

    def __init__(self, status_code: int, excerpt: str, retries: int) -> None:
        self.status_code = status_code
        self.excerpt = excerpt
        self.retries = retries
        super().__init__(f"HTTP {status_code}: {excerpt}")


def estimate_tokens(text: str) -> int:
    """A rough token count for servers that do not report usage."""
    return math.ceil(len(text) / CHARS_PER_TOKEN)


def schema_instruction(schema: dict[str, Any]) -> str:
    """The system-prompt text that asks for JSON when the server cannot enforce a schema."""
    return (
        "Answer with exactly one JSON object and nothing else. "
        "It must conform to this JSON schema:\n"
        f"```json\n{json.dumps(schema, separators=(',', ':'), sort_keys=True)}\n```"
    )


def _schema_name(request: ChatRequest) -> str:
    # OpenAI allows [A-Za-z0-9_-]{1,64}; anything else becomes "_".
    raw = request.schema_name or f"{request.agent}_output"
    cleaned = "".join(c if c.isascii() and (c.isalnum() or c in "_-") else "_" for c in raw)
    return cleaned[:64] or "output"


def _excerpt(response: httpx.Response) -> str:
    text = response.text.strip().replace("\n", " ")
    if len(text) > _ERROR_EXCERPT_CHARS:
        return text[:_ERROR_EXCERPT_CHARS] + "…"
    return text


def _mentions_response_format(excerpt: str) -> bool:
    lowered = excerpt.lower()
    return any(word in lowered for word in _RESPONSE_FORMAT_WORDS)


def _content_text(message: dict[str, Any]) -> str:
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


def _usage(data: dict[str, Any], messages: list[dict[str, str]], text: str) -> Usage:
    reported = data.get("usage")
    prompt = completion = None
    if isinstance(reported, dict):
        prompt = _token_count(reported.get("prompt_tokens"))
        completion = _token_count(reported.get("completion_tokens"))
    if prompt is not None and completion is not None:
        return Usage(prompt_tokens=prompt, completion_tokens=completion)
    if prompt is None:
        prompt = _prompt_estimate(messages)
    if completion is None:
        completion = estimate_tokens(text)
    return Usage(prompt_tokens=prompt, completion_tokens=completion, estimated=True)


class OpenAICompatibleModel(ChatModel):
    """``POST {base_url}/chat/completions`` over one pooled ``httpx.AsyncClient``."""

    def __init__(
        self,
        base_url: str,
        model: str,
        *,
        api_key: SecretStr | str | None = None,
        timeout_s: float = 60.0,
        temperature: float = 0.0,
        seed: int | None = 0,
        max_tokens: int | None = None,
        retry: RetryPolicy | None = None,
        log_bodies: bool = True,
        transport: httpx.AsyncBaseTransport | None = None,
        structured: StructuredSetting = "auto",
        stream: bool = False,
        call_budget_s: float | None = None,
        retry_local_timeouts: bool = False,
    ) -> None:
        super().__init__()
        if not base_url.startswith(("http://", "https://")):
            raise ValueError(f"LLM base URL must start with http:// or https://: {base_url!r}")
        if timeout_s <= 0:
            raise ValueError("timeout_s must be positive")
        self.base_url = base_url.rstrip("/")
        self.model = model
        self._api_key = SecretStr(api_key) if isinstance(api_key, str) else api_key
        self.timeout_s = timeout_s
        self.temperature = temperature
        self.seed = seed
        self.max_tokens = max_tokens
        self.retry = retry if retry is not None else RetryPolicy(seed=seed)
        self.log_bodies = log_bodies
        self._transport = transport
        self._client: httpx.AsyncClient | None = None
        if call_budget_s is not None and call_budget_s <= 0:
            raise ValueError("call_budget_s must be positive")
        self.structured: StructuredSetting = structured
        self.stream = stream
        self.call_budget_s = call_budget_s
        self.retry_timeouts = retry_local_timeouts or not is_local_url(self.base_url)
        # The best structured-output mode this server has not refused yet.
        self._structured_mode: StructuredMode = (
            "json_schema" if structured == "auto" else structured
        )

    @classmethod
    def from_settings(
        cls, settings: Settings, *, retry: RetryPolicy | None = None
    ) -> OpenAICompatibleModel:
        if not settings.llm_base_url:
            raise ValueError("ASSISTANTX_LLM_BASE_URL is not set; the LLM reasoner is off")
        return cls(
            settings.llm_base_url,
            settings.llm_model,
            api_key=settings.llm_api_key,
            timeout_s=settings.llm_timeout_s,
            temperature=settings.llm_temperature,
            seed=settings.llm_seed,
            max_tokens=settings.llm_max_tokens,
            retry=retry
            if retry is not None
            else RetryPolicy(max_retries=settings.llm_max_retries, seed=settings.llm_seed),
            structured=settings.llm_structured_output,
            stream=settings.llm_stream,
            call_budget_s=settings.llm_call_budget_s,
        )

    def __repr__(self) -> str:
        return f"{type(self).__name__}(base_url={self.base_url!r}, model={self.model!r})"

    @property
    def structured_mode(self) -> StructuredMode:
        """How the next schema request will be sent (falls back as the server refuses)."""
        return self._structured_mode

    @property
    def enforces_schema(self) -> bool:
        """Whether the server is (as far as we know) made to follow the schema itself."""
        return self._structured_mode in ENFORCED_MODES

    @property
    def endpoint(self) -> str:
        return f"{self.base_url}/chat/completions"

    async def _start(self) -> None:
        headers = {"Accept": "application/json"}
        if self._api_key is not None and self._api_key.get_secret_value():
            headers["Authorization"] = f"Bearer {self._api_key.get_secret_value()}"
        self._client = httpx.AsyncClient(
            headers=headers, timeout=httpx.Timeout(self.timeout_s), transport=self._transport
        )

    async def _stop(self) -> None:
        client, self._client = self._client, None
        if client is not None:
            await client.aclose()

    async def _complete(self, request: ChatRequest) -> ChatResponse:
        started = time.perf_counter()
        mode: StructuredMode = self._structured_mode if request.json_schema else "none"
        retries = 0
        while True:
            body = self._body(request, mode)
            if self.log_bodies and logger.isEnabledFor(logging.DEBUG):
                logger.debug(
                    "LLM request agent=%s mode=%s messages=%s",
                    request.agent,
                    mode,
                    json.dumps(body["messages"], ensure_ascii=False),
                )
            try:
                data, used_retries = await self._post(body, request.agent)
            except _ResponseFormatRejected as exc:
                retries += exc.retries
                mode = self._fall_back(mode, exc)
                continue
            except _Failed as exc:
                raise LLMCallFailed(
                    str(exc),
                    user_text=exc.user_text,
                    usage=Usage(
                        prompt_tokens=_prompt_estimate(body["messages"]) * exc.tries,
                        completion_tokens=estimate_tokens(exc.partial_text),
                        estimated=True,
                    ),
                    latency_s=time.perf_counter() - started,
                    model=self.model,
                    retries=retries + exc.tries - 1,
                ) from exc.__cause__
            retries += used_retries
            break
        return self._response(data, body, request, mode, retries, time.perf_counter() - started)

    def _fall_back(self, refused: StructuredMode, exc: _ResponseFormatRejected) -> StructuredMode:
        following = _FALLBACK_ORDER.get(refused)
        if self.structured != "auto" or following is None:
            raise LLMCallFailed(
                f"{self.endpoint} refused response_format {refused} ({exc}); "
                "set ASSISTANTX_LLM_STRUCTURED_OUTPUT to a mode it supports",
                user_text="my language model server does not accept the answer format I need",
                usage=Usage(),
                latency_s=0.0,
                model=self.model,
            ) from exc
        # Another call may have fallen back already; never skip a mode because of a race.
        if self._structured_mode == refused:
            self._structured_mode = following
            logger.warning(
                "LLM server %s refused response_format %s (%s); using %s from now on",
                self.base_url,
                refused,
                exc,
                following,
            )
        return self._structured_mode

    def _body(self, request: ChatRequest, mode: StructuredMode) -> dict[str, Any]:
        messages = [m.model_dump() for m in request.messages]
        if request.json_schema is not None and mode in ("json_object", "prompt"):
            messages = _with_schema_instruction(messages, request.json_schema)
        body: dict[str, Any] = {
            "model": self.model,
            "messages": messages,
            "temperature": self.temperature,
            "stream": self.stream,
        }
        if self.seed is not None:
            body["seed"] = self.seed
        if self.max_tokens is not None:
            body["max_tokens"] = self.max_tokens
        if mode == "json_schema" and request.json_schema is not None:
            body["response_format"] = {
                "type": "json_schema",
                "json_schema": {
                    "name": _schema_name(request),
                    "schema": request.json_schema,
                    "strict": request.schema_strict,
                },
            }
        elif mode == "json_object_schema" and request.json_schema is not None:
            body["response_format"] = {"type": "json_object", "schema": request.json_schema}
        elif mode == "json_object":
            body["response_format"] = {"type": "json_object"}
        return body

    async def _post(self, body: dict[str, Any], agent: str) -> tuple[dict[str, Any], int]:
        """POST with retries; returns the decoded JSON and how many retries it took."""
        client = self._client
        if client is None:
            raise RuntimeError(f"{self!r} is not started")
        headers = {AGENT_HEADER: agent} if agent.isascii() and agent.isprintable() else {}
        attempts = self.retry.max_retries + 1
        failure: Exception | None = None
        partial = _Partial()
        user_text = "my language model server did not answer"
        for attempt in range(attempts):
            retry_after_s: float | None = None
            partial = _Partial()
            retryable = True
            try:
                async with asyncio.timeout(self.call_budget_s):
                    outcome = await self._exchange(client, body, headers, partial)
            except httpx.UnsupportedProtocol as exc:
                raise LLMError(f"{self.endpoint}: {exc}") from exc
            except (httpx.TimeoutException, TimeoutError) as exc:
                failure = exc
                limit = self.timeout_s if isinstance(exc, httpx.TimeoutException) else None
                reason = (
                    f"no answer within {limit:g} s ({type(exc).__name__})"
                    if limit is not None
                    else f"the call took longer than its {self.call_budget_s:g} s budget"
                )
                user_text = "my language model server took too long to answer"
                retryable = self.retry_timeouts
            except httpx.TransportError as exc:
                failure = exc
                reason = f"connection failed ({type(exc).__name__}: {exc})"
                user_text = "I could not reach my language model server"
            else:
                if isinstance(outcome, dict):
                    return outcome, attempt
                response = outcome
                excerpt = _excerpt(response)
                status_error = httpx.HTTPStatusError(
                    f"HTTP {response.status_code}: {excerpt}",
                    request=response.request,
                    response=response,
                )
                if "response_format" in body and _refuses_response_format(
                    response.status_code, excerpt
                ):
                    raise _ResponseFormatRejected(response.status_code, excerpt, attempt)
                if not is_retryable_status(response.status_code):
                    raise LLMCallFailed(
                        f"{self.endpoint} answered HTTP {response.status_code}: {excerpt}",
                        user_text="my language model server refused the request",
                        usage=Usage(),
                        latency_s=0.0,
                        model=self.model,
                        retries=attempt,
                    ) from status_error
                failure = status_error
                reason = f"HTTP {response.status_code}"
                user_text = "my language model server kept failing"
                retry_after_s = parse_retry_after(response.headers.get("retry-after"))
            if attempt + 1 == attempts or not retryable:
                break
            delay_s = self.retry.delay_s(attempt, retry_after_s)
            logger.warning(
                "LLM call for %s failed: %s; retry %d of %d in %.2f s",
                agent,
                reason,
                attempt + 1,
                self.retry.max_retries,
                delay_s,
            )
            await asyncio.sleep(delay_s)
        tries = attempt + 1
        error = _Failed(
            f"{self.endpoint} failed after {tries} attempt(s); last error: {reason}",
            user_text=user_text,
            tries=tries,
            partial_text=partial.text,
        )
        error.__cause__ = failure
        raise error

    async def _exchange(
        self,
        client: httpx.AsyncClient,
        body: dict[str, Any],
        headers: dict[str, str],
        partial: _Partial,
    ) -> dict[str, Any] | httpx.Response:
        """One HTTP exchange: the decoded answer, or the error response to judge."""
        if not body.get("stream"):
            response = await client.post(self.endpoint, json=body, headers=headers)
            return self._decode(response) if response.is_success else response
        async with client.stream("POST", self.endpoint, json=body, headers=headers) as response:
            if not response.is_success or "text/event-stream" not in response.headers.get(
                "content-type", ""
            ):
                await response.aread()
                return self._decode(response) if response.is_success else response
            async for line in response.aiter_lines():
                if not line.startswith("data:"):
                    continue
                payload = line[5:].strip()
                if payload == "[DONE]":
                    break
                partial.add(self._chunk(payload))
        return partial.as_completion(self.model)

    def _chunk(self, payload: str) -> dict[str, Any]:
        try:
            chunk = json.loads(payload)
        except ValueError as exc:
            raise LLMError(f"{self.endpoint} streamed a chunk that is not JSON") from exc
        if not isinstance(chunk, dict):
            raise LLMError(f"{self.endpoint} streamed a chunk that is not an object")
        if isinstance(chunk.get("error"), dict | str):
            raise LLMError(f"{self.endpoint} reported an error mid-stream: {chunk['error']}")
        return chunk

    def _decode(self, response: httpx.Response) -> dict[str, Any]:
        try:
            data = response.json()
        except ValueError as exc:
            raise LLMError(
                f"{self.endpoint} answered with a body that is not JSON: {_excerpt(response)}"
            ) from exc
        choices = data.get("choices") if isinstance(data, dict) else None
        if not isinstance(choices, list) or not choices or not isinstance(choices[0], dict):
            raise LLMError(f"{self.endpoint} answered without choices: {_excerpt(response)}")
        message = choices[0].get("message")
        if not isinstance(message, dict):
            raise LLMError(f"{self.endpoint} answered without a message: {_excerpt(response)}")
        return data  # type: ignore[no-any-return]

    def _response(
        self,
        data: dict[str, Any],
        body: dict[str, Any],
        request: ChatRequest,
        mode: StructuredMode,
        retries: int,
        latency_s: float,
    ) -> ChatResponse:
        choice = data["choices"][0]
        text = _content_text(choice["message"])
        usage = _usage(data, body["messages"], text)
        finish_reason = choice.get("finish_reason")
        model = data.get("model")
        response = ChatResponse(
            text=text,
            usage=usage,
            latency_s=latency_s,
            model=model if isinstance(model, str) and model else self.model,
            finish_reason=finish_reason if isinstance(finish_reason, str) else None,
            retries=retries,
            structured_mode=mode,
        )
        if self.log_bodies:
            logger.debug("LLM response agent=%s text=%s", request.agent, text)
        logger.debug(
            "LLM call agent=%s tokens=%d+%d%s latency=%.3f s retries=%d",
            request.agent,
            usage.prompt_tokens,
            usage.completion_tokens,
            " (estimated)" if usage.estimated else "",
            latency_s,
            retries,
        )
        return response


class _Failed(Exception):
    """Every try failed (internal; ``_complete`` turns it into ``LLMCallFailed``)."""

    def __init__(self, message: str, *, user_text: str, tries: int, partial_text: str) -> None:
        super().__init__(message)
        self.user_text = user_text
        self.tries = tries
        self.partial_text = partial_text


class _Partial:
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


def _prompt_estimate(messages: list[dict[str, str]]) -> int:
    return estimate_tokens("".join(m["content"] for m in messages))


def _refuses_response_format(status_code: int, excerpt: str) -> bool:
    if status_code in (400, 422):
        return _mentions_response_format(excerpt)
    # Some llama.cpp forks answer 500 "response_format type must be one of ...".
    return status_code >= 500 and "response_format" in excerpt.lower()


def _with_schema_instruction(
    messages: list[dict[str, str]], schema: dict[str, Any]
) -> list[dict[str, str]]:
    instruction = schema_instruction(schema)
    if messages and messages[0]["role"] == "system":
        first = {"role": "system", "content": f"{messages[0]['content']}\n\n{instruction}"}
        return [first, *messages[1:]]
    return [{"role": "system", "content": instruction}, *messages]
