"""The ASGI app: ``create_app(settings)``; the lifespan builds the runtime (adapters entered
through an AsyncExitStack) and tears it down in reverse order. Nothing runs at import time."""

from __future__ import annotations

import logging
import time
from collections.abc import AsyncIterator, Callable
from contextlib import AsyncExitStack, asynccontextmanager
from pathlib import Path

from fastapi import FastAPI
from fastapi.responses import FileResponse
from fastapi.staticfiles import StaticFiles
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from assistantx.core.settings import Settings
from assistantx.service import (
    dashboard,
    devices,
    events,
    health,
    instructions,
    memory,
    messages,
    metrics,
    reports,
)
from assistantx.service.datalock import DataDirLock
from assistantx.service.errors import error_body, install_error_handlers
from assistantx.service.runtime import ServiceRuntime

logger = logging.getLogger(__name__)

STATIC_DIR = Path(__file__).resolve().parents[1] / "static"


OWN_BODY_LIMITS = ("/_matrix/app/",)
"""Routes that cap their bodies themselves, at their protocol's size and in its error format
(a Matrix transaction may hold 100 events of 64 KiB; a 413 the homeserver cannot read would
make it retry the transaction for ever)."""


class BodyLimit:
    """Answers 413 when a request body exceeds ``max_bytes`` (declared or streamed), except
    on the paths under ``own_limits``."""

    def __init__(self, app: ASGIApp, max_bytes: int, own_limits: tuple[str, ...] = ()) -> None:
        self.app = app
        self.max_bytes = max_bytes
        self.own_limits = own_limits

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or str(scope["path"]).startswith(self.own_limits):
            await self.app(scope, receive, send)
            return
        declared = dict(scope["headers"]).get(b"content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.max_bytes):
            await _too_large(send, self.max_bytes)
            return
        seen = 0
        started = False

        async def limited_receive() -> Message:
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.max_bytes:
                    raise _TooLargeError
            return message

        async def tracking_send(message: Message) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, limited_receive, tracking_send)
        except _TooLargeError:
            if not started:
                await _too_large(send, self.max_bytes)


class _TooLargeError(Exception):
    pass


async def _too_large(send: Send, limit: int) -> None:
    import json

    body = json.dumps(
        error_body("payload_too_large", f"the request body exceeds {limit} bytes")
    ).encode()
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


def create_app(
    settings: Settings | None = None,
    *,
    on_ready: Callable[[ServiceRuntime], None] | None = None,
    data_lock: DataDirLock | None = None,
) -> FastAPI:
    """The app; ``on_ready`` is called once the assistant runs (the CLI prints where to go);
    ``data_lock``: the data folder's lock, when the caller holds it already."""
    settings = settings or Settings()
    runtime = ServiceRuntime(settings, data_lock)

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        async with AsyncExitStack() as stack:
            await runtime.start(stack)
            logger.info("assistant ready (%s reasoner)", runtime.assistant.parts.reasoner_name)
            if on_ready is not None:
                on_ready(runtime)
            yield

    app = FastAPI(
        title="AssistantX",
        version="0.1.0",
        description="A proactive office assistant: instructions, live traces, memory, chats.",
        lifespan=lifespan,
        # The stock Swagger UI and ReDoc load their scripts from a CDN and stay blank offline;
        # /docs is our own page (static/docs.html) reading /openapi.json, served from here.
        docs_url=None,
        redoc_url=None,
    )
    app.state.runtime = runtime
    install_error_handlers(app)

    @app.middleware("http")
    async def count_requests(request, call_next):  # type: ignore[no-untyped-def]
        started = time.perf_counter()
        response = await call_next(request)
        route = request.scope.get("route")
        path = getattr(route, "path", "unmatched")
        if runtime.ready:
            seconds = time.perf_counter() - started
            runtime.metrics.request_served(request.method, path, response.status_code, seconds)
        return response

    for module in (health, instructions, events, memory, messages, devices, metrics, dashboard):
        app.include_router(module.router)
    app.include_router(reports.router)  # also starts surveys (router lifespan)
    if runtime.matrix is not None:
        app.include_router(runtime.matrix.push_router)  # the homeserver's pushes

    @app.get("/docs", include_in_schema=False)
    async def api_docs() -> FileResponse:
        return FileResponse(STATIC_DIR / "docs.html", media_type="text/html")

    if STATIC_DIR.is_dir():
        app.mount("/", StaticFiles(directory=STATIC_DIR, html=True), name="static")
    app.add_middleware(BodyLimit, max_bytes=settings.max_body_bytes, own_limits=OWN_BODY_LIMITS)
    return app
