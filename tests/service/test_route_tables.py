"""The app's route tables are built before the service is ready: its first requests analyse
no endpoint (FastAPI did that at the first request to each router, on the event loop)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import fastapi.routing
import pytest

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.route_tables import build_route_tables
from service.inprocess import serving_runtime


@pytest.fixture
def analysed(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The paths of the endpoints FastAPI analyses from now on (a spy: it still analyses)."""
    seen: list[str] = []
    context = fastapi.routing._EffectiveRouteContext
    original = context.from_api_route.__func__  # type: ignore[attr-defined]

    def spy(cls: type, *args: Any, **kwargs: Any) -> Any:
        seen.append(kwargs["original_route"].path)
        return original(cls, *args, **kwargs)

    monkeypatch.setattr(context, "from_api_route", classmethod(spy))
    return seen


def test_building_analyses_every_endpoint_once(tmp_path: Path, analysed: list[str]) -> None:
    app = create_app(Settings(data_dir=tmp_path / "data"))
    assert build_route_tables(app) > 1
    assert "/v1/instructions" in analysed and "/v1/instructions/{instruction_id}" in analysed
    first = len(analysed)
    build_route_tables(app)
    assert len(analysed) == first  # built once, kept


async def test_the_first_requests_after_ready_analyse_nothing(
    tmp_path: Path, analysed: list[str]
) -> None:
    async with serving_runtime(tmp_path / "data") as (client, _runtime):
        assert "/v1/instructions" in analysed  # at start-up
        before = len(analysed)
        r = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "Please bring me a stapler."}
        )
        assert r.status_code == 202, r.text
        assert (await client.get(f"/v1/instructions/{r.json()['id']}")).status_code == 200
        assert (await client.get("/v1/robot")).status_code == 200
        assert len(analysed) == before
