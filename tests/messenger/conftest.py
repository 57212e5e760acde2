"""A real uvicorn server on 127.0.0.1 for the routers under test, and a real SQLite store."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator, Callable
from pathlib import Path

import pytest
import pytest_asyncio
from fastapi import APIRouter, FastAPI

from assistantx.adapters.messenger.matrix import SqliteEventStore
from assistantx.core.ports.messenger import InboundMessage
from helpers.servers import serve_asgi

ServeRouters = Callable[..., contextlib.AbstractAsyncContextManager[str]]


@pytest.fixture
def serve_routers() -> ServeRouters:
    @contextlib.asynccontextmanager
    async def serve(*routers: APIRouter) -> AsyncIterator[str]:
        app = FastAPI()
        for router in routers:
            app.include_router(router)
        async with serve_asgi(app) as url:
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
