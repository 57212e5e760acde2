"""An in-process app served by a real uvicorn server on 127.0.0.1, with an httpx client."""

from __future__ import annotations

from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.server import service_server
from helpers.servers import running
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
    async with (
        running(server),
        httpx.AsyncClient(base_url=f"http://127.0.0.1:{port}", timeout=10) as client,
    ):
        yield client
