"""Real uvicorn servers on 127.0.0.1 inside the test's event loop."""

from __future__ import annotations

import asyncio
import contextlib
import socket
from collections.abc import AsyncIterator, Iterator
from typing import Any

import httpx
import uvicorn
from fastapi import FastAPI

from assistantx.service.server import ServiceServer, service_server
from helpers.eventually import eventually
from helpers.quiet_server import QuietServer


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@contextlib.contextmanager
def refusing_port() -> Iterator[int]:
    """A port where connections are refused for as long as the block runs: the socket is
    bound and never listens, so the kernel answers every connect with a reset. A port that
    was free a moment ago (``free_port``) can be taken by a server another test starts."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        yield port


@contextlib.asynccontextmanager
async def running(server: uvicorn.Server, *, timeout_s: float = 30.0) -> AsyncIterator[None]:
    """Serve in this loop; enter once it listens (uvicorn has no event for that, only its
    ``started`` flag), and stop it on exit. A server that fails to start raises its error."""
    task = asyncio.create_task(server.serve())

    def listening() -> bool:
        if task.done():
            task.result()  # raises what stopped it
            raise RuntimeError("uvicorn stopped during start-up")
        return bool(server.started)

    try:
        await eventually(listening, what="uvicorn to listen", timeout_s=timeout_s)
        yield
    finally:
        if isinstance(server, QuietServer):
            server.request_exit()
        else:
            server.should_exit = True  # seen on its next 0.1 s tick
        await task


@contextlib.asynccontextmanager
async def serve_asgi(app: Any, port: int | None = None) -> AsyncIterator[str]:
    """A bare ASGI app (no lifespan) on ``port`` (a free one by default); yields its URL."""
    config = uvicorn.Config(
        app,
        host="127.0.0.1",
        port=port or free_port(),
        lifespan="off",
        log_level="warning",
        ws="none",
        http="h11",
    )
    async with running(QuietServer(config)):
        yield f"http://127.0.0.1:{config.port}"


class _QuietServiceServer(ServiceServer, QuietServer):
    """The service's own server (its config, and its stop that ends the live event streams
    first) with the quiet server's timing: a stop as soon as asked, without uvicorn's 0.1 s
    tick and fixed 0.1 s sleep (some 0.2 s of every in-process service's stop; the suites
    start well over a hundred). What a stop does is the service's; only the waits differ."""


def _quiet(server: ServiceServer) -> _QuietServiceServer:
    return _QuietServiceServer(server.config, server.offices)


@contextlib.asynccontextmanager
async def serving_app(app: FastAPI, **client: Any) -> AsyncIterator[httpx.AsyncClient]:
    """An app made by ``create_app``, served by the service's own uvicorn server (with the
    quiet server's waits) on a free port; yields an httpx client of it (``client``: its
    options; a 10 s timeout by default)."""
    port = free_port()
    server = _quiet(service_server(app, "127.0.0.1", port, log_level="warning"))
    options: dict[str, Any] = {"timeout": 10, **client}
    async with (
        running(server),
        httpx.AsyncClient(base_url=f"http://127.0.0.1:{port}", **options) as http,
    ):
        yield http
