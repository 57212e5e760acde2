"""An in-process app served by a real uvicorn server on 127.0.0.1, with an httpx client."""

from __future__ import annotations

from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest

from service.inprocess import running_service


@pytest.fixture
async def api(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    async with running_service(tmp_path / "data", max_body_bytes=4096) as client:
        yield client
