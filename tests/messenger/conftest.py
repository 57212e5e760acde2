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
from assistantx.core.ports.messenger import InboundMessage

ServeRouters = Callable[..., contextlib.AbstractAsyncContextManager[str]]


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
