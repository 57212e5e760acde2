"""A scripted OpenAI-compatible chat-completions server for tests.

It runs for real (FastAPI under uvicorn, bound to 127.0.0.1 on a free port, as a task in the
test's event loop) and answers every ``POST /v1/chat/completions`` from a script:

* a queue of replies per agent. The agent is recognized from the ``X-AssistantX-Agent``
  header our client sends, else from an ``AGENT: <name>`` line in a system message, else
  from the ``json_schema`` name; replies scripted for ``"*"`` serve any agent;
* or a handler, a callable that computes the reply from the recorded request, used when the
  agent's queue (and the ``"*"`` queue) is empty.

A reply is a :class:`Reply`, a string (the message content) or a dict (sent as JSON content).
Helpers build the awkward cases: :func:`malformed_json`, :func:`prose_around`,
:func:`rate_limited`, :func:`server_error`, :func:`slow`, :func:`reject_response_format`,
and ``usage=None`` for a server that reports no usage. Server-wide switches emulate what
older servers do: ``supports_json_schema = False`` answers 400 to any ``json_schema``
response_format (before the script is consulted), ``supports_json_object = False`` likewise,
and ``api_key`` makes it answer 401 unless that bearer token is sent.

Every request is recorded in ``requests`` with the status it got. A request with nothing
scripted gets a 400 naming the agent, and is counted in ``unscripted``.

Usage::

    async def test_x(scripted_llm: ScriptedLLM) -> None:
        scripted_llm.script("planning", rate_limited(0.01), {"goal": "g", "subgoals": []})
        model = OpenAICompatibleModel(scripted_llm.base_url, "m")
"""

from __future__ import annotations

import asyncio
import contextlib
import dataclasses
import json
import socket
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from types import TracebackType
from typing import Any, Literal, Self

import uvicorn
from fastapi import FastAPI, Request
from fastapi.responses import JSONResponse, Response

from helpers.eventually import eventually
from helpers.quiet_server import QuietServer

AGENT_HEADER = "x-assistantx-agent"
ANY_AGENT = "*"

UsageSpec = dict[str, int] | Literal["auto"] | None


@dataclass(frozen=True)
class Reply:
    """One scripted answer.

    ``usage="auto"`` reports whitespace-token counts, ``None`` leaves ``usage`` out, a dict
    is sent as given. ``raw_body`` replaces the whole HTTP body (to send something that is
    not JSON at all). ``delay_s`` waits before answering (to provoke client timeouts).
    """

    content: str | None = ""
    status: int = 200
    usage: UsageSpec = "auto"
    finish_reason: str = "stop"
    headers: dict[str, str] = field(default_factory=dict)
    delay_s: float = 0.0
    error: str | None = None
    raw_body: str | None = None


@dataclass(frozen=True)
class RecordedRequest:
    """What the client sent, and how the server answered it."""

    index: int
    path: str
    headers: dict[str, str]
    body: dict[str, Any]
    agent: str | None
    status: int = 0

    @property
    def messages(self) -> list[dict[str, Any]]:
        messages = self.body.get("messages")
        return messages if isinstance(messages, list) else []

    @property
    def response_format(self) -> dict[str, Any] | None:
        value = self.body.get("response_format")
        return value if isinstance(value, dict) else None

    @property
    def system_text(self) -> str:
        return "\n".join(
            str(m.get("content", "")) for m in self.messages if m.get("role") == "system"
        )

    @property
    def last_user_text(self) -> str:
        users = [m for m in self.messages if m.get("role") == "user"]
        return str(users[-1].get("content", "")) if users else ""

    @property
    def text(self) -> str:
        """Every message's content, one per line (for 'contains' assertions)."""
        return "\n".join(str(m.get("content", "")) for m in self.messages)


Handler = Callable[[RecordedRequest], "Reply | str | dict[str, Any]"]
ScriptItem = Reply | str | dict[str, Any] | Handler


# -- reply helpers --------------------------------------------------------------------------


def json_reply(value: dict[str, Any], *, usage: UsageSpec = "auto") -> Reply:
    return Reply(content=json.dumps(value), usage=usage)


def malformed_json() -> Reply:
    """JSON cut off in the middle, as a model that ran out of tokens writes it."""
    return Reply(
        content='{"goal": "fetch the document", "subgoals": [{"description": ',
        finish_reason="length",
    )


def prose_around(value: dict[str, Any]) -> Reply:
    """The JSON inside a code fence with chatter before and after."""
    return Reply(
        content=f"Sure! Here is my answer:\n```json\n{json.dumps(value, indent=2)}\n```\n"
        "Let me know if you need anything else."
    )


def rate_limited(retry_after: float | str | None = 0, *, message: str = "Rate limit") -> Reply:
    headers = {} if retry_after is None else {"Retry-After": str(retry_after)}
    return Reply(status=429, headers=headers, error=message)


def server_error(status: int = 500, message: str = "internal server error") -> Reply:
    return Reply(status=status, error=message)


def slow(delay_s: float, content: str | dict[str, Any] = "late") -> Reply:
    """An answer that arrives after ``delay_s`` (longer than the client timeout, usually)."""
    text = json.dumps(content) if isinstance(content, dict) else content
    return Reply(content=text, delay_s=delay_s)


def reject_response_format(status: int = 400) -> Reply:
    return Reply(
        status=status,
        error="response_format type must be one of 'text' or 'json_object', but got: json_schema",
    )


# -- the server -----------------------------------------------------------------------------


def _usage_for(body: dict[str, Any], content: str | None) -> dict[str, int]:
    prompt = sum(
        len(str(m.get("content", "")).split())
        for m in body.get("messages", [])
        if isinstance(m, dict)
    )
    completion = len((content or "").split())
    return {
        "prompt_tokens": prompt,
        "completion_tokens": completion,
        "total_tokens": prompt + completion,
    }


def _recognize_agent(headers: dict[str, str], body: dict[str, Any]) -> str | None:
    if headers.get(AGENT_HEADER):
        return headers[AGENT_HEADER]
    for message in body.get("messages", []):
        if isinstance(message, dict) and message.get("role") == "system":
            for line in str(message.get("content", "")).splitlines():
                if line.strip().upper().startswith("AGENT:"):
                    return line.split(":", 1)[1].strip() or None
    response_format = body.get("response_format")
    if isinstance(response_format, dict):
        schema = response_format.get("json_schema")
        if isinstance(schema, dict) and isinstance(schema.get("name"), str):
            return str(schema["name"])
    return None


class ScriptedLLM:
    """The scripted server; ``async with ScriptedLLM() as llm`` or the ``scripted_llm`` fixture."""

    def __init__(self, *, model: str = "scripted-model") -> None:
        self.model = model
        self.requests: list[RecordedRequest] = []
        self.unscripted = 0
        self.supports_json_schema = True
        self.supports_json_object = True
        # answer ``stream: true`` requests as server-sent events (chunks of the content, then
        # the usage chunk when ``stream_options.include_usage`` asks for it)
        self.streams = False
        self.api_key: str | None = None
        self._queues: dict[str, deque[ScriptItem]] = {}
        self._handlers: dict[str, Handler] = {}
        self._server: QuietServer | None = None
        self._task: asyncio.Task[None] | None = None
        self._socket: socket.socket | None = None
        self._closing = asyncio.Event()
        self.port = 0

    # -- scripting ---------------------------------------------------------------------

    def script(self, agent: str = ANY_AGENT, *replies: ScriptItem) -> None:
        """Queue replies for ``agent`` (``"*"``: any agent), answered in order."""
        self._queues.setdefault(agent, deque()).extend(replies)

    def respond_with(self, handler: Handler, agent: str = ANY_AGENT) -> None:
        """Compute replies for ``agent`` whenever its queue is empty."""
        self._handlers[agent] = handler

    def pending(self, agent: str | None = None) -> int:
        """Replies not yet consumed (for one agent, or all)."""
        if agent is not None:
            return len(self._queues.get(agent, ()))
        return sum(len(q) for q in self._queues.values())

    def requests_for(self, agent: str) -> list[RecordedRequest]:
        return [r for r in self.requests if r.agent == agent]

    @property
    def base_url(self) -> str:
        if not self.port:
            raise RuntimeError("the scripted LLM server is not running")
        return f"http://127.0.0.1:{self.port}/v1"

    # -- lifecycle ---------------------------------------------------------------------

    async def start(self) -> None:
        if self._task is not None:
            return
        sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        # asyncio sets TCP_NODELAY only on sockets created with proto=IPPROTO_TCP; without it
        # Nagle and delayed ACKs add ~40 ms to every small response.
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        sock.bind(("127.0.0.1", 0))
        self._socket = sock
        self.port = sock.getsockname()[1]
        config = uvicorn.Config(
            self._app(),
            log_level="warning",
            access_log=False,
            lifespan="off",
            ws="none",
            http="h11",
            timeout_graceful_shutdown=2,
        )
        self._server = QuietServer(config)
        self._task = asyncio.create_task(self._server.serve(sockets=[sock]))
        server, task = self._server, self._task

        def listening() -> bool:
            if task.done():
                task.result()  # raises what made the server fail
                raise RuntimeError("the scripted LLM server stopped during start-up")
            return bool(server.started)

        await eventually(
            listening, what="the scripted LLM server to listen", timeout_s=10, interval_s=0.005
        )

    async def stop(self) -> None:
        if self._task is None or self._server is None:
            return
        self._closing.set()  # wake replies that are still waiting out their delay
        self._server.request_exit()
        try:
            await self._task
        finally:
            self._task = None
            self._server = None
            if self._socket is not None:
                self._socket.close()
                self._socket = None

    async def __aenter__(self) -> Self:
        await self.start()
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        await self.stop()

    # -- serving -----------------------------------------------------------------------

    def _app(self) -> FastAPI:
        app = FastAPI(openapi_url=None, docs_url=None, redoc_url=None)

        @app.post("/v1/chat/completions")
        async def chat_completions(request: Request) -> Response:
            return await self._answer(request)

        @app.get("/v1/models")
        async def models() -> dict[str, Any]:
            return {"object": "list", "data": [{"id": self.model, "object": "model"}]}

        return app

    async def _answer(self, request: Request) -> Response:
        headers = {k.lower(): v for k, v in request.headers.items()}
        try:
            body = json.loads(await request.body())
        except ValueError:
            body = None
        valid = isinstance(body, dict)
        body = body if isinstance(body, dict) else {}
        agent = _recognize_agent(headers, body)
        index = len(self.requests)
        recorded = RecordedRequest(index, request.url.path, headers, body, agent)
        self.requests.append(recorded)  # in arrival order; the status is filled in below
        if not valid:
            response: Response = _error(400, "body is not a JSON object")
        else:
            response = await self._respond(recorded)
        self.requests[index] = dataclasses.replace(recorded, status=response.status_code)
        return response

    async def _respond(self, recorded: RecordedRequest) -> Response:
        refusal = self._refusal(recorded.headers, recorded.body)
        if refusal is not None:
            return refusal
        item = self._next_item(recorded.agent)
        if item is None:
            self.unscripted += 1
            return _error(
                400,
                f"scripted_llm: nothing scripted for agent {recorded.agent!r} "
                f"(request #{recorded.index})",
            )
        reply = _as_reply(item(recorded) if callable(item) else item)
        if reply.delay_s > 0:
            with contextlib.suppress(TimeoutError):
                await asyncio.wait_for(self._closing.wait(), timeout=reply.delay_s)
        return self._render(reply, recorded.body)

    def _refusal(self, headers: dict[str, str], body: dict[str, Any]) -> Response | None:
        if self.api_key is not None and headers.get("authorization") != f"Bearer {self.api_key}":
            return _error(401, "invalid or missing API key", kind="authentication_error")
        response_format = body.get("response_format")
        kind = response_format.get("type") if isinstance(response_format, dict) else None
        if (kind == "json_schema" and not self.supports_json_schema) or (
            kind == "json_object" and not self.supports_json_object
        ):
            return _error(400, f"response_format type {kind!r} is not supported by this server")
        return None

    def _next_item(self, agent: str | None) -> ScriptItem | None:
        for key in (agent, ANY_AGENT):
            queue = self._queues.get(key) if key is not None else None
            if queue:
                return queue.popleft()
        for key in (agent, ANY_AGENT):
            if key is not None and key in self._handlers:
                return self._handlers[key]
        return None

    def _render(self, reply: Reply, body: dict[str, Any]) -> Response:
        if reply.raw_body is not None:
            return Response(
                reply.raw_body,
                status_code=reply.status,
                headers=reply.headers,
                media_type="application/json",
            )
        if reply.status >= 400:
            return _error(reply.status, reply.error or "scripted error", headers=reply.headers)
        if self.streams and body.get("stream") is True:
            return self._stream(reply, body)
        payload: dict[str, Any] = {
            "id": f"chatcmpl-scripted-{len(self.requests) - 1}",
            "object": "chat.completion",
            "created": int(time.time()),
            "model": str(body.get("model") or self.model),
            "choices": [
                {
                    "index": 0,
                    "message": {"role": "assistant", "content": reply.content},
                    "finish_reason": reply.finish_reason,
                }
            ],
        }
        if reply.usage == "auto":
            payload["usage"] = _usage_for(body, reply.content)
        elif reply.usage is not None:
            payload["usage"] = reply.usage
        return JSONResponse(payload, status_code=reply.status, headers=reply.headers)

    def _stream(self, reply: Reply, body: dict[str, Any]) -> Response:
        model = str(body.get("model") or self.model)
        content = reply.content or ""
        pieces = [content[i : i + 8] for i in range(0, len(content), 8)]
        chunks: list[dict[str, Any]] = [
            {"model": model, "choices": [{"index": 0, "delta": {"content": piece}}]}
            for piece in pieces
        ]
        chunks.append(
            {"model": model, "choices": [{"index": 0, "delta": {}, "finish_reason": "stop"}]}
        )
        options = body.get("stream_options")
        if isinstance(options, dict) and options.get("include_usage") and reply.usage is not None:
            usage = _usage_for(body, reply.content) if reply.usage == "auto" else reply.usage
            chunks.append({"model": model, "choices": [], "usage": usage})
        text = "".join(f"data: {json.dumps(c)}\n\n" for c in chunks) + "data: [DONE]\n\n"
        return Response(text, media_type="text/event-stream", headers=reply.headers)


def _as_reply(value: Reply | str | dict[str, Any]) -> Reply:
    if isinstance(value, Reply):
        return value
    if isinstance(value, dict):
        return json_reply(value)
    return Reply(content=value)


def _error(
    status: int,
    message: str,
    *,
    kind: str = "invalid_request_error",
    headers: dict[str, str] | None = None,
) -> JSONResponse:
    if status == 429:
        kind = "rate_limit_error"
    elif status >= 500:
        kind = "server_error"
    return JSONResponse(
        {"error": {"message": message, "type": kind, "code": status}},
        status_code=status,
        headers=headers,
    )
