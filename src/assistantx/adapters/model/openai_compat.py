"""A chat model on any OpenAI-compatible ``/chat/completions`` endpoint.

Tested against the protocol as OpenAI, vLLM, Ollama (``/v1``) and llama.cpp's server speak
it. The concerns live apart: the wire format and usage in ``_wire`` (servers that omit usage
get an estimate, marked ``estimated``), the structured-output modes and their fallback in
``_modes``, retries in the shared transport (:mod:`assistantx.core.http_retry`); this module
sends one call and accounts for it.

* Cost. ``max_tokens`` caps each completion; ``call_budget_s`` bounds one call's wall time,
  retries included. With ``stream=True`` the answer is streamed, so a call that runs out of
  time closes the connection and the server stops generating for nobody (llama.cpp and vLLM
  do); a server that answers a streamed request with plain JSON is read as plain JSON.
* Accounting. Every request sent is a try (``ChatResponse.retries`` counts the extra ones):
  a refused connection is a try that cost no tokens; a try that timed out or broke off cost
  the prompt (estimated) and what was streamed so far. The server's own counts are used
  whenever it sends them.

Transport failures (429, 5xx, timeouts, refused or dropped connections) are retried with
seeded exponential backoff and jitter, honouring ``Retry-After`` up to a cap, except a timeout
against a server on this machine: it is busy with our own earlier work, and a retry would
queue behind it. After the last try an ``LLMCallFailed`` carries the cause, the cost and a
cause in plain words. The API key goes out as a bearer token and is never logged; prompt and
completion bodies are logged at DEBUG only, and not at all with ``log_bodies=False``.
"""

from __future__ import annotations

import asyncio
import dataclasses
import json
import logging
import time
from typing import TYPE_CHECKING, Any

import httpx
from pydantic import SecretStr

from assistantx.adapters.model._modes import (
    FALLBACK_ORDER,
    BodyOptions,
    StructuredSetting,
    refuses_response_format,
    request_body,
)
from assistantx.adapters.model._wire import (
    StreamedAnswer,
    content_text,
    decode_answer,
    estimate_tokens,
    excerpt,
    parse_chunk,
    prompt_estimate,
    usage_of,
)
from assistantx.core.errors import LLMError
from assistantx.core.http_retry import TRIES, RetryingTransport, RetryPolicy, Try
from assistantx.core.ports.model import (
    ENFORCED_MODES,
    ChatModel,
    ChatRequest,
    ChatResponse,
    FailureKind,
    LLMCallFailed,
    StructuredMode,
    Usage,
)

if TYPE_CHECKING:
    from assistantx.core.settings import Settings

logger = logging.getLogger(__name__)

AGENT_HEADER = "X-AssistantX-Agent"
_LOCAL_HOSTS = frozenset({"127.0.0.1", "localhost", "::1", "0.0.0.0", "[::1]"})


def is_local_url(url: str) -> bool:
    """True for a server on this machine (whose timeouts are not worth retrying)."""
    host = httpx.URL(url).host
    return host in _LOCAL_HOSTS or host.startswith("127.")


class _ResponseFormatRejected(Exception):
    """The server refused the ``response_format`` we sent (internal signal)."""

    def __init__(self, status_code: int, excerpt: str, tries: int) -> None:
        self.status_code = status_code
        self.excerpt = excerpt
        self.tries = tries
        super().__init__(f"HTTP {status_code}: {excerpt}")


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
        policy = dataclasses.replace(self.retry, retry_timeouts=self.retry_timeouts)
        self._client = httpx.AsyncClient(
            headers=headers,
            timeout=httpx.Timeout(self.timeout_s),
            transport=RetryingTransport(policy, self._transport, final=_refused_format),
        )

    async def _stop(self) -> None:
        client, self._client = self._client, None
        if client is not None:
            await client.aclose()

    async def _complete(self, request: ChatRequest) -> ChatResponse:
        started = time.perf_counter()
        mode: StructuredMode = self._structured_mode if request.json_schema else "none"
        tries = 0  # requests sent for this call, across mode fallbacks
        while True:
            body = request_body(request, mode, self._options)
            if self.log_bodies and logger.isEnabledFor(logging.DEBUG):
                logger.debug(
                    "LLM request agent=%s mode=%s messages=%s",
                    request.agent,
                    mode,
                    json.dumps(body["messages"], ensure_ascii=False),
                )
            try:
                data, sent = await self._post(body, request.agent)
            except _ResponseFormatRejected as exc:
                tries += exc.tries
                mode = self._fall_back(mode, exc)
                continue
            except _Failed as exc:
                raise LLMCallFailed(
                    str(exc),
                    user_text=exc.user_text,
                    usage=exc.cost(prompt_estimate(body["messages"])),
                    latency_s=time.perf_counter() - started,
                    model=self.model,
                    retries=tries + len(exc.tries) - 1,
                    kind=exc.kind,
                ) from exc.__cause__
            tries += sent
            break
        return self._response(data, body, request, mode, tries - 1, time.perf_counter() - started)

    @property
    def _options(self) -> BodyOptions:
        return BodyOptions(self.model, self.temperature, self.seed, self.max_tokens, self.stream)

    def _fall_back(self, refused: StructuredMode, exc: _ResponseFormatRejected) -> StructuredMode:
        following = FALLBACK_ORDER.get(refused)
        if self.structured != "auto" or following is None:
            raise LLMCallFailed(
                f"{self.endpoint} refused response_format {refused} ({exc}); "
                "set ASSISTANTX_LLM_STRUCTURED_OUTPUT to a mode it supports",
                user_text="my language model server does not accept the answer format I need",
                kind="unsupported",
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

    async def _post(self, body: dict[str, Any], agent: str) -> tuple[dict[str, Any], int]:
        """One call (the transport retries); the decoded answer and how many requests it
        took, or ``_Failed`` with every try."""
        client = self._client
        if client is None:
            raise RuntimeError(f"{self!r} is not started")
        headers = {AGENT_HEADER: agent} if agent.isascii() and agent.isprintable() else {}
        tries: list[Try] = []
        partial = StreamedAnswer()
        try:
            async with asyncio.timeout(self.call_budget_s):
                outcome = await self._exchange(client, body, headers, partial, tries)
        except httpx.UnsupportedProtocol as exc:
            raise LLMError(f"{self.endpoint}: {exc}") from exc
        except TimeoutError as exc:  # the call's budget, mid-request
            _cut_off(tries, Try("timed_out", error="call budget"))
            raise self._failed(
                f"the call took longer than its {self.call_budget_s:g} s budget",
                "my language model server took too long to answer",
                tries,
                partial,
                exc,
            ) from exc
        except httpx.TimeoutException as exc:
            if not tries or tries[-1].outcome != "timed_out":  # timed out reading the body
                _cut_off(tries, Try("timed_out", error=type(exc).__name__))
            raise self._failed(
                f"no answer within {self.timeout_s:g} s ({type(exc).__name__})",
                "my language model server took too long to answer",
                tries,
                partial,
                exc,
            ) from exc
        except httpx.TransportError as exc:
            if not tries or tries[-1].outcome == "answered":  # broke off reading the body
                _cut_off(tries, Try("failed", error=type(exc).__name__))
            refused = tries[-1].outcome == "refused"
            raise self._failed(
                f"connection failed ({type(exc).__name__}: {exc})",
                "I could not reach my language model server"
                if refused
                else "my language model server broke off its answer",
                tries,
                partial,
                exc,
            ) from exc
        if isinstance(outcome, dict):
            return outcome, len(tries)
        response = outcome
        text = excerpt(response)
        status_error = httpx.HTTPStatusError(
            f"HTTP {response.status_code}: {text}", request=response.request, response=response
        )
        if "response_format" in body and refuses_response_format(response.status_code, text):
            raise _ResponseFormatRejected(response.status_code, text, len(tries))
        if response.status_code >= 500 or response.status_code == 429:
            raise self._failed(
                f"HTTP {response.status_code}",
                "my language model server kept failing",
                tries,
                partial,
                status_error,
            )
        raise LLMCallFailed(
            f"{self.endpoint} answered HTTP {response.status_code}: {text}",
            user_text="my language model server refused the request",
            kind="rejected",
            usage=Usage(),
            latency_s=0.0,
            model=self.model,
            retries=len(tries) - 1,
        ) from status_error

    def _failed(
        self,
        reason: str,
        user_text: str,
        tries: list[Try],
        partial: StreamedAnswer,
        cause: Exception,
    ) -> _Failed:
        error = _Failed(
            f"{self.endpoint} failed after {len(tries)} attempt(s); last error: {reason}",
            user_text=user_text,
            tries=tries,
            partial_text=partial.text,
        )
        last = tries[-1] if tries else None
        if last is None or last.outcome == "failed":
            error.kind = "broken"
        elif last.outcome == "answered":
            error.kind = "server_error"
        else:
            error.kind = last.outcome
        error.__cause__ = cause
        return error

    async def _exchange(
        self,
        client: httpx.AsyncClient,
        body: dict[str, Any],
        headers: dict[str, str],
        partial: StreamedAnswer,
        tries: list[Try],
    ) -> dict[str, Any] | httpx.Response:
        """One exchange (its tries recorded in ``tries``): the decoded answer, or the error
        response to judge."""
        extensions = {TRIES: tries}
        if not body.get("stream"):
            response = await client.post(
                self.endpoint, json=body, headers=headers, extensions=extensions
            )
            return decode_answer(response, self.endpoint) if response.is_success else response
        async with client.stream(
            "POST", self.endpoint, json=body, headers=headers, extensions=extensions
        ) as response:
            if not response.is_success or "text/event-stream" not in response.headers.get(
                "content-type", ""
            ):
                await response.aread()
                if response.is_success:
                    return decode_answer(response, self.endpoint)
                return response
            async for line in response.aiter_lines():
                if not line.startswith("data:"):
                    continue
                payload = line[5:].strip()
                if payload == "[DONE]":
                    break
                partial.add(parse_chunk(payload, self.endpoint))
        return partial.as_completion(self.model)

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
        text = content_text(choice["message"])
        usage = usage_of(data, body["messages"], text)
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


def _cut_off(tries: list[Try], outcome: Try) -> None:
    """Record how the request in flight ended: a streamed answer whose headers came (a try
    already recorded as answered) and whose body never finished is the same request, not
    another one; a request cut off before any answer is a try of its own."""
    if tries and tries[-1].outcome == "answered" and (tries[-1].status or 0) < 300:
        tries[-1] = outcome
    else:
        tries.append(outcome)


def _refused_format(request: httpx.Request, response: httpx.Response) -> bool:
    """A 5xx that refuses the response_format we sent: falling back beats retrying."""
    sent = b'"response_format"' in request.content
    return sent and refuses_response_format(response.status_code, excerpt(response))


class _Failed(Exception):
    """Every try failed (internal; ``_complete`` turns it into ``LLMCallFailed``)."""

    def __init__(
        self, message: str, *, user_text: str, tries: list[Try], partial_text: str
    ) -> None:
        super().__init__(message)
        self.user_text = user_text
        self.tries = tries
        self.partial_text = partial_text
        self.kind: FailureKind = "broken"

    def cost(self, prompt_tokens: int) -> Usage:
        """An estimate of what the failed tries cost: the prompt for each try the server was
        reading when it timed out or broke off, and what was streamed; nothing for a refused
        connection or an error status (the server answered without generating)."""
        read = sum(1 for t in self.tries if t.outcome in ("timed_out", "failed"))
        return Usage(
            prompt_tokens=prompt_tokens * read,
            completion_tokens=estimate_tokens(self.partial_text),
            estimated=True,
        )


__all__ = ["AGENT_HEADER", "OpenAICompatibleModel", "StructuredSetting", "estimate_tokens"]
