"""GET /v1/events replays a bounded number of journaled events, never a year of them."""

from __future__ import annotations

import asyncio
import json
from collections.abc import AsyncIterator
from pathlib import Path

import httpx
import pytest

from assistantx.core.events import TraceEvent
from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.runtime import ServiceRuntime
from assistantx.store.journal import EventRecord, Journal
from helpers.servers import serving_app
from service.server import OPERATOR

AUTH = {"Authorization": f"Bearer {OPERATOR}"}


# An event the hub sends live once a stream has begun (never journaled): everything a stream
# sends before it is its replay, read to the end without waiting out a quiet window.
LIVE = EventRecord(
    seq=1_000_000,
    event=TraceEvent(instruction_id="ins-old", kind="observation", time=999.0, step=999),
)


@pytest.fixture
async def journaled(tmp_path: Path) -> AsyncIterator[tuple[httpx.AsyncClient, ServiceRuntime]]:
    """A service whose journal already holds 40 events (times 100..139) of a finished run."""
    data = tmp_path / "data"
    journal = Journal.open(data / "journal.sqlite3")
    journal.create_instruction("ins-old", "lee", "t", 1.0)
    journal.set_status("ins-old", "done")
    for n in range(40):
        event = TraceEvent(instruction_id="ins-old", kind="observation", time=100.0 + n, step=n)
        journal.record(event)
    journal.close()
    app = create_app(Settings(data_dir=data, operator_token=OPERATOR, robot_localize=False))
    async with serving_app(app) as client:
        yield client, app.state.runtime


async def _replayed(
    service: tuple[httpx.AsyncClient, ServiceRuntime], path: str, headers: dict[str, str]
) -> list[dict]:
    """The events the stream replays: those it sends before a live event, published once the
    stream has sent its first (its listener is subscribed before the replay begins)."""
    client, runtime = service
    got: list[dict] = []

    async def read() -> None:
        async with client.stream("GET", path, headers={**AUTH, **headers}) as response:
            assert response.status_code == 200
            async for line in response.aiter_lines():
                if not line.startswith("data: "):
                    continue
                event = json.loads(line[6:])
                if event.get("step") == LIVE.event.step:
                    return
                if not got:
                    runtime.hub.publish(LIVE)
                got.append(event)

    await asyncio.wait_for(read(), 30)
    return got


async def test_replay_is_the_newest_events_by_default(
    journaled: tuple[httpx.AsyncClient, ServiceRuntime],
) -> None:
    got = await _replayed(journaled, "/v1/events?replay=5", {})
    assert [e["step"] for e in got] == [35, 36, 37, 38, 39]


async def test_replay_since_a_time(journaled: tuple[httpx.AsyncClient, ServiceRuntime]) -> None:
    got = await _replayed(journaled, "/v1/events?since=136", {})
    assert [e["step"] for e in got] == [36, 37, 38, 39]


async def test_a_reconnect_beyond_the_cap_is_told_what_it_missed(
    journaled: tuple[httpx.AsyncClient, ServiceRuntime],
) -> None:
    got = await _replayed(journaled, "/v1/events?replay=3", {"Last-Event-ID": "10"})
    assert got[0]["kind"] == "replay_truncated"
    assert got[0]["skipped_after"] == 10
    assert [e["step"] for e in got[1:]] == [37, 38, 39]
    within = await _replayed(journaled, "/v1/events", {"Last-Event-ID": "37"})
    assert [e["step"] for e in within] == [37, 38, 39]  # ids start at 1: id 38 is step 37
