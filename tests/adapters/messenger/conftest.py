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
from assistantx.adapters.messenger.matrix.appservice import PUSH_PATH_PREFIX, push_too_large_error
from assistantx.core.ports.messenger import InboundMessage
from assistantx.service.body_limit import BodyLimit, PathLimit
from helpers.servers import serve_asgi

ServeRouters = Callable[..., contextlib.AbstractAsyncContextManager[str]]

# A push-mode config whose homeserver is a closed port: for tests that send nothing out.
PUSH_YAML = """
homeserver_url: http://127.0.0.1:9
server_name: office.test
as_token: as-token
hs_token: hs-token
mode: push
people: {lee: "@lee:office.test"}
max_retries: 0
"""

PUSH_BODY_LIMIT = PathLimit(PUSH_PATH_PREFIX, 4096, push_too_large_error)
"""The routers are served behind the service's body limit, with a small push limit for tests."""


@pytest.fixture
def serve_routers() -> ServeRouters:
    @contextlib.asynccontextmanager
    async def serve(*routers: APIRouter) -> AsyncIterator[str]:
        app = FastAPI()
        for router in routers:
            app.include_router(router)
        app.add_middleware(BodyLimit, max_bytes=64 * 1024, paths=(PUSH_BODY_LIMIT,))
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
