"""The one request-size limit of the app: an ASGI middleware answering 413 before a route
parses a body that is too large, declared (Content-Length) or streamed (chunked, or a sender
that lies about its length).

Most routes share ``max_bytes`` and get the API's error body. A protocol pushing to us can
have its own limit and error body under its path prefix (``PathLimit``): a Matrix homeserver
pushes transactions of up to 16 MiB and reads a 413 only in Matrix's error format.

Why not the framework's: FastAPI 0.165 / Starlette 1.10 do ship one (``max_body_size`` on the
app, a router or a route: Starlette's ``RequestBodyLimitMiddleware``), but it answers a
declared oversize body itself with a fixed ``text/plain`` "Content Too Large", past the app's
exception handlers, and it only counts the bytes a route reads. Neither our JSON error (which
names the limit) nor Matrix's ``M_TOO_LARGE`` could be given, and clients of both parse those.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from assistantx.service.errors import error_body

ErrorBody = Callable[[int], dict[str, Any]]
"""The JSON body of a 413 for a limit of so many bytes."""


def api_error_body(limit_bytes: int) -> dict[str, Any]:
    return error_body("payload_too_large", f"the request body exceeds {limit_bytes} bytes")


@dataclass(frozen=True)
class PathLimit:
    """Bodies of requests under ``prefix`` may have ``max_bytes``; a 413 carries ``error``."""

    prefix: str
    max_bytes: int
    error: ErrorBody


class BodyLimit:
    """Answers 413 when a request body exceeds its limit: the first ``PathLimit`` whose prefix
    the path starts with, else ``max_bytes`` with the API's error body."""

    def __init__(self, app: ASGIApp, max_bytes: int, paths: Sequence[PathLimit] = ()) -> None:
        self.app = app
        self.default = PathLimit("/", max_bytes, api_error_body)
        self.paths = tuple(paths)

    def limit_for(self, path: str) -> PathLimit:
        return next((p for p in self.paths if path.startswith(p.prefix)), self.default)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        limit = self.limit_for(str(scope["path"]))
        declared = dict(scope["headers"]).get(b"content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > limit.max_bytes):
            await _too_large(send, limit)
            return
        seen = 0
        exceeded = False
        started = False  # the app's answer began before the limit was exceeded
        answered = False  # the 413 went out in place of whatever the app answers

        async def limited_receive() -> Message:
            nonlocal seen, exceeded
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > limit.max_bytes:
                    exceeded = True
                    raise _TooLargeError
            return message

        async def guarded_send(message: Message) -> None:
            # A framework may catch the receive error and answer on its own (FastAPI turns
            # any failure to read a body into "400 There was an error parsing the body"):
            # once the limit is exceeded, the answer is our 413 whatever the app sends.
            nonlocal answered, started
            if not exceeded or started:
                started = started or message["type"] == "http.response.start"
                await send(message)
            elif not answered and message["type"] == "http.response.start":
                answered = True
                await _too_large(send, limit)

        try:
            await self.app(scope, limited_receive, guarded_send)
        except _TooLargeError:
            pass
        if exceeded and not answered and not started:
            await _too_large(send, limit)


class _TooLargeError(Exception):
    pass


async def _too_large(send: Send, limit: PathLimit) -> None:
    body = json.dumps(limit.error(limit.max_bytes)).encode()
    await send(
        {
            "type": "http.response.start",
            "status": 413,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(body)).encode()),
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})
