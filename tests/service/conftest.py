"""An in-process app served by a real uvicorn server on 127.0.0.1, with an httpx client."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.server import service_server
from service.server import LEE, OPERATOR, ZHANG, free_port


@pytest.fixture
async def api(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    import json

    settings = Settings(
        data_dir=tmp_path / "data",
        operator_token=OPERATOR,
        tokens=json.dumps({LEE: "lee", ZHANG: "zhang"}),
        speedup=50,
        max_body_bytes=4096,
    )
    port = free_port()
    server = service_server(create_app(settings), "127.0.0.1", port, log_level="warning")
    task = asyncio.create_task(server.serve())
    for _ in range(500):  # uvicorn offers no event for "listening"
        if server.started:
            break
        await asyncio.sleep(0.02)
    async with httpx.AsyncClient(base_url=f"http://127.0.0.1:{port}", timeout=10) as client:
        yield client
    server.should_exit = True
    await task
