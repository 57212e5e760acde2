"""Three offices over two real replica processes on the tests' PostgreSQL: the offices spread
(at most ceil(3/2) = 2 each), a SIGTERM hands a replica's offices to the other at once, and a
``kill -9`` moves them once their leases expire; ``GET /v1/offices`` and ``/metrics`` of
either replica say which replica runs which office."""

from __future__ import annotations

import asyncio
import time
from collections import Counter
from pathlib import Path
from typing import Any

import httpx
import psycopg
import pytest

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from helpers.eventually import eventually, eventually_sync
from helpers.servers import serving_app
from service.inprocess import serving_runtime
from service.replicas import deployment, replica
from service.server import OPERATOR, Server
from service.standby import holders

pytestmark = pytest.mark.postgres

TTL_S = 2.0
HEADERS = {"Authorization": f"Bearer {OPERATOR}"}
OFFICES = ["annex", "harbour", "hq"]


def _replica(folder: Path, name: str, url: str, offices: Path) -> Server:
    return replica(folder, name, url, offices, ASSISTANTX_LEASE_TTL_S=str(TTL_S))


def settle(server: Server, until: Any, what: str, timeout_s: float = 60) -> dict[str, Any]:
    result: dict[str, Any] = eventually_sync(
        lambda: holders(server), until=until, what=what, timeout_s=timeout_s
    )
    return result


def spread(view: dict[str, str | None]) -> list[int]:
    return sorted(Counter(view.values()).values())


def replica_series(server: Server) -> dict[str, str]:
    text = httpx.get(f"{server.url}/metrics", headers=HEADERS, timeout=10).text
    found: dict[str, str] = {}
    for line in text.splitlines():
        if line.startswith("assistantx_office_replica{"):
            labels = dict(
                part.split("=", 1)
                for part in line[line.index("{") + 1 : line.index("}")].split(",")
            )
            found[labels["office"].strip('"')] = labels["replica"].strip('"')
    return found


def replica_health(server: Server) -> dict[str, float]:
    """``assistantx_replica_up`` by replica, as ``server`` answers ``/metrics``."""
    text = httpx.get(f"{server.url}/metrics", headers=HEADERS, timeout=10).text
    found: dict[str, float] = {}
    for line in text.splitlines():
        if line.startswith("assistantx_replica_up{"):
            replica = line[line.index('replica="') + 9 : line.index('"}')]
            found[replica] = float(line.rsplit(" ", 1)[1])
    return found


async def test_one_office_on_replicas_lists_the_lease_holder(
    tmp_path: Path, postgres_url: str
) -> None:
    """One office (no deployment file) under a lease: /v1/offices names the replica holding
    it, as the lease does (its generated name, when none is configured)."""
    async with serving_runtime(
        tmp_path, database_url=postgres_url, lease_ttl_s=TTL_S, robot="sim"
    ) as (api, runtime):
        assert runtime.office_lease is not None and runtime.office_lease.lease is not None
        [office] = (await api.get("/v1/offices")).json()
        assert office["replica"] == runtime.office_lease.lease.holder
        assert (office["id"], office["here"], office["status"]) == ("default", True, "ready")


@pytest.mark.slow
def test_offices_spread_over_replicas_and_move_when_one_leaves(
    tmp_path: Path, postgres_url: str
) -> None:
    offices = deployment(tmp_path, "hq", "harbour", "annex")
    a = _replica(tmp_path, "replica-a", postgres_url, offices)
    b: Server | None = None
    try:
        # Alone, A runs every office.
        settle(a, lambda v: set(v.values()) == {"replica-a"}, "replica A to run all offices")
        # B joins: A hands one office back and B takes it; 2 and 1, never more than 2.
        b = _replica(tmp_path, "replica-b", postgres_url, offices)
        view = settle(
            a,
            lambda v: None not in v.values() and spread(v) == [1, 2],
            "the offices to spread over A and B",
        )
        assert set(view.values()) == {"replica-a", "replica-b"}
        assert settle(b, lambda v: v == view, "B to see the same spread") == view
        assert replica_series(b) == view  # /metrics of either replica names the holders
        assert replica_health(b) == {"replica-a": 1.0, "replica-b": 1.0}
        # Each office's journal is in its own schema: one per office but the home one.
        with psycopg.connect(postgres_url, autocommit=True) as db:
            schemas = {r[0] for r in db.execute("SELECT nspname FROM pg_namespace")}
        assert {"office_harbour", "office_annex"} <= schemas

        # SIGTERM: B hands its office over at once (no wait for the lease to expire).
        b.stop()
        stopped = time.monotonic()
        settle(a, lambda v: set(v.values()) == {"replica-a"}, "A to take B's office back")
        assert time.monotonic() - stopped < 30

        # B again, then kill -9 A: its offices move to B once their leases expire.
        b = _replica(tmp_path, "replica-b", postgres_url, offices)
        settle(b, lambda v: None not in v.values() and spread(v) == [1, 2], "the spread again")
        a.kill()
        settle(
            b,
            lambda v: set(v.values()) == {"replica-b"},
            "B to take A's offices once their leases expired",
        )
        r = httpx.get(f"{b.url}/v1/offices/harbour/me", headers=HEADERS, timeout=10)
        assert r.status_code == 200, r.text  # the moved office answers on B
        # The killed replica is no longer up once its heartbeat expired (0, then gone).
        eventually_sync(
            lambda: replica_health(b),
            until=lambda health: (
                health.get("replica-a", 0.0) == 0.0 and health.get("replica-b") == 1.0
            ),
            what="B's /metrics to say A is down",
            timeout_s=30,
        )
    finally:
        a.stop()
        if b is not None:
            b.stop()


async def test_a_replica_that_loses_one_office_stops_that_office_only(
    tmp_path: Path, postgres_url: str
) -> None:
    """Another replica takes Harbour Street's lease (as after this one paused past it): this
    replica stops Harbour Street, keeps running the others, and does not take it back while
    the other's lease holds."""
    settings = Settings(
        data_dir=tmp_path / "data",
        offices=deployment(tmp_path, "hq", "harbour", "annex"),
        database_url=postgres_url,
        lease_ttl_s=TTL_S,
        replica_id="replica-a",
        operator_token=OPERATOR,
        robot="sim",
        speedup=50,
    )
    async with serving_app(create_app(settings), headers=HEADERS) as api:

        async def view() -> dict[str, tuple[str | None, str]]:
            offices = (await api.get("/v1/offices")).json()
            return {o["id"]: (o["replica"], o["status"]) for o in offices}

        everywhere = {office: ("replica-a", "ready") for office in OFFICES}
        await eventually(view, until=lambda v: v == everywhere, what="A to run every office")
        with psycopg.connect(postgres_url, autocommit=True) as db:
            db.execute(
                "UPDATE leases SET holder='replica-b', token=token+1, expires_at=%s"
                " WHERE office='harbour'",
                (time.time() + 600,),
            )
        moved = {**everywhere, "harbour": ("replica-b", "elsewhere")}
        await eventually(view, until=lambda v: v == moved, what="A to stop Harbour Street")
        r = await api.get("/v1/offices/harbour/robot")  # the robot is the holder's to tell
        assert r.status_code == 503
        assert r.json()["message"] == "the office Harbour Street is run by replica replica-b"
        # Instructions are read from the shared journal (``offices.submissions``).
        assert (await api.get("/v1/offices/harbour/instructions")).status_code == 200
        assert (await api.get("/v1/offices/annex/instructions")).status_code == 200
        # A negative, so no event to wait on: three rounds pass and A leaves the office alone.
        for _ in range(3):
            await asyncio.sleep(TTL_S / 3)
        assert await view() == moved
