"""A real uvicorn server on 127.0.0.1 for the routers under test, and a real SQLite store."""

from __future__ import annotations

import asyncio
import contextlib
import socket
from collections.abc import AsyncIterator, Callable
from pathlib import Path
from typing import Any

import pytest
import pytest_asyncio
import uvicorn
from fastapi import APIRouter, FastAPI

from assistantx.adapters.messenger.matrix import SqliteEventStore
from assistantx.adapters.messenger.matrix.appservice import PUSH_PATH_PREFIX, push_too_large_error
from assistantx.core.ports.messenger import InboundMessage
from assistantx.service.body_limit import BodyLimit, PathLimit

ServeRouters = Callable[..., contextlib.AbstractAsyncContextManager[str]]

PUSH_BODY_LIMIT = PathLimit(PUSH_PATH_PREFIX, 4096, push_too_large_error)
"""The routers are served behind the service's body limit, with a small push limit for tests."""


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@contextlib.asynccontextmanager
async def serve_app(app: Any) -> AsyncIterator[str]:
    config = uvicorn.Config(
        app,
        host="127.0.0.1",
        port=_free_port(),
        lifespan="off",
        log_level="warning",
        ws="none",
        http="h11",
    )
    server = uvicorn.Server(config)
    task = asyncio.create_task(server.serve())
    while not server.started:
        if task.done():
            task.result()
            raise RuntimeError("uvicorn did not start")
        await asyncio.sleep(0.01)
    try:
        yield f"http://127.0.0.1:{config.port}"
    finally:
        server.should_exit = True
        await task


@pytest.fixture
def serve_routers() -> ServeRouters:
    @contextlib.asynccontextmanager
    async def serve(*routers: APIRouter) -> AsyncIterator[str]:
        app = FastAPI()
        for router in routers:
            app.include_router(router)
        app.add_middleware(BodyLimit, max_bytes=64 * 1024, paths=(PUSH_BODY_LIMIT,))
        async with serve_app(app) as url:
            yield url

    return serve


@pytest_asyncio.fixture
async def store(tmp_path: Path) -> AsyncIterator[SqliteEventStore]:
    events = SqliteEventStore(tmp_path / "events.db")
    yield events
    await events.close()


@pytest.fixture
def inbox() -> asyncio.Queue[InboundMessage]:
    return asyncio.Queue()
