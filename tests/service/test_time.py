"""Timestamps are real time whatever the speed-up; the speed-up shortens simulated durations
only, defaults to 1 with real people, and the service states it (/readyz, the page)."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import httpx
import pytest

from assistantx.core.clock import WallClock
from assistantx.core.settings import Settings
from helpers.eventually import eventually
from service.inprocess import running_service
from service.server import LEE, OPERATOR

AS_LEE = {"Authorization": f"Bearer {LEE}"}
OP = {"Authorization": f"Bearer {OPERATOR}"}
SLACK_S = 3.0  # scheduling on a loaded machine, not speed-up (10x of 2 s would be 18 s off)


def _real(stamp: float, since: float) -> bool:
    return since - SLACK_S <= stamp <= time.time() + SLACK_S


async def _instruction(api: httpx.AsyncClient, iid: str) -> dict[str, Any]:
    body: dict[str, Any] = (await api.get(f"/v1/instructions/{iid}", headers=AS_LEE)).json()
    return body


async def test_with_a_speedup_every_timestamp_is_real_time(tmp_path: Path) -> None:
    # With a speed-up of 10,000 a sped-up clock would run hours ahead after the server's
    # start alone (any real millisecond is 10 s), far beyond the slack: no wait needed.
    async with running_service(tmp_path / "data", speedup=10_000) as api:
        assert (await api.get("/readyz")).json()["speedup"] == 10_000
        since = time.time()
        r = await api.post(
            "/v1/instructions", json={"requester": "lee", "text": "a stapler"}, headers=AS_LEE
        )
        assert r.status_code == 202
        iid = r.json()["id"]
        assert _real(r.json()["created_at"], since) and _real(r.json()["updated_at"], since)
        body = await eventually(
            lambda: _instruction(api, iid),
            until=lambda b: b["trace"] and len(b["trace"]["steps"]) >= 2,
            what="the instruction to take two steps",
        )
        assert _real(body["trace"]["started_at"], since)
        assert all(_real(s["started_at"], since) for s in body["trace"]["steps"])
        messages = (await api.get("/v1/chats/dm/wang", headers=OP)).json()
        assert messages and all(_real(m["time"], since) for m in messages)


async def test_real_time_stays_real_over_a_restart(tmp_path: Path) -> None:
    # The first run's start and stop alone would put a 10,000-times clock minutes ahead.
    async with running_service(tmp_path / "data", speedup=10_000) as api:
        assert (await api.get("/readyz")).status_code == 200
    async with running_service(tmp_path / "data", speedup=10_000) as api:
        since = time.time()
        r = await api.post(
            "/v1/instructions", json={"requester": "lee", "text": "a stapler"}, headers=AS_LEE
        )
        assert _real(r.json()["created_at"], since)


@pytest.mark.parametrize(
    ("people", "stated", "expected"),
    [("simulated", None, 10.0), ("human", None, 1.0), ("human", 5.0, 5.0), ("simulated", 2.0, 2.0)],
)
def test_the_speedup_defaults_to_1_with_real_people(
    people: str, stated: float | None, expected: float
) -> None:
    assert Settings(people=people, speedup=stated).effective_speedup == expected  # type: ignore[arg-type]


async def test_real_people_get_real_time_and_the_speedup_is_stated(tmp_path: Path) -> None:
    async with running_service(tmp_path / "data", people="human", speedup=None) as api:
        assert (await api.get("/readyz")).json()["speedup"] == 1
    async with running_service(tmp_path / "other", people="human", speedup=4) as api:
        assert (await api.get("/readyz")).json()["speedup"] == 4


def test_a_sped_up_wall_clock_keeps_the_time_of_day() -> None:
    clock = WallClock(speedup=1000)
    before = time.time()
    assert before <= clock.now() <= time.time()
    assert clock.speedup == 1000
