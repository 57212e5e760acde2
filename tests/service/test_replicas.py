"""Replicas on one PostgreSQL: one runs the office under its lease, another waits as a standby
and takes the office over (resuming its unfinished instruction) when the first one stops."""

from __future__ import annotations

import asyncio
from pathlib import Path
from typing import Any

import pytest

from helpers.eventually import eventually
from service.inprocess import serving_runtime
from service.test_codes_after_restart import SLOW_LENDER, submit

pytestmark = pytest.mark.postgres

TTL_S = 3.0  # short, so the standby's tries and the holder's renewals come every second


async def test_a_standby_takes_the_office_over_at_a_clean_shutdown_and_resumes(
    tmp_path: Path, postgres_url: str
) -> None:
    shared: dict[str, Any] = {**SLOW_LENDER, "database_url": postgres_url, "lease_ttl_s": TTL_S}
    b_started, b_may_stop = asyncio.Event(), asyncio.Event()
    seen: dict[str, Any] = {}

    async def replica_b(iid: str) -> None:
        async with serving_runtime(tmp_path / "b", **shared, replica_id="replica-b") as (
            api,
            runtime,
        ):
            seen["resumed"] = list(runtime.resumed)
            seen["status"] = (await api.get(f"/v1/instructions/{iid}")).json()["status"]
            assert runtime.office_lease is not None and runtime.office_lease.lease is not None
            seen["token"] = runtime.office_lease.lease.token
            b_started.set()
            await b_may_stop.wait()

    async with serving_runtime(tmp_path / "a", **shared, replica_id="replica-a") as (api, a):
        assert a.office_lease is not None and a.office_lease.lease is not None
        first = a.office_lease.lease
        iid = await submit(api)
        b = asyncio.create_task(replica_b(iid))
        # B tries while A renews: A's lease is extended twice and B has not started.
        await eventually(
            lambda: (
                a.office_lease is not None
                and a.office_lease.lease is not None
                and a.office_lease.lease.expires_at > first.expires_at + TTL_S / 2
            ),
            what="replica A to renew its lease",
        )
        assert not b_started.is_set() and not b.done()
    # A's clean shutdown released the office: B takes it at its next try and resumes.
    await asyncio.wait_for(b_started.wait(), 30)
    b_may_stop.set()
    await b
    assert iid in seen["resumed"] and seen["status"] in ("queued", "running")
    assert seen["token"] == first.token + 1
