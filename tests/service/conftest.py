"""An in-process app served by a real uvicorn server on 127.0.0.1, with an httpx client; and
one map cache for every in-process service of a test process."""

from __future__ import annotations

from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest

from assistantx.service import runtime as service_runtime
from service.inprocess import running_service


@pytest.fixture
async def api(tmp_path: Path) -> AsyncIterator[httpx.AsyncClient]:
    async with running_service(tmp_path / "data", max_body_bytes=4096) as client:
        yield client


@pytest.fixture(scope="session")
def _map_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("map-cache")


@pytest.fixture(autouse=True)
def _one_map_cache(_map_cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The arrays a service derives from its map (distance transforms, the planner's landmark
    tables: `nav.disk_cache`, named by the hash of what they are computed from) are kept in one
    folder per test process, not under each test's fresh data folder, where every service
    computed them again (~0.1 CPU-s a start). An absolute name joined to the data folder is
    that name. The tests of the cache itself (tests/nav/test_disk_cache.py, the CLI's) keep
    their own folders; `assistantx serve` in a subprocess its data folder's."""
    monkeypatch.setattr(service_runtime, "MAP_CACHE_DIR", str(_map_cache))
