"""Replicas on one PostgreSQL: one runs the office under its lease, another waits as a standby
and takes the office over (resuming its unfinished instruction) when the first one stops."""

from __future__ import annotations

import asyncio
import json
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import httpx
import psycopg
import pytest

from helpers.eventually import eventually, eventually_sync
from helpers.instructions import submit_stapler
from helpers.processes import wait_ready
from service.inprocess import serving_runtime
from service.server import OPERATOR, base_env, free_port, serve
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
            seen["metrics"] = await lease_series(api)
            b_started.set()
            await b_may_stop.wait()

    async with serving_runtime(tmp_path / "a", **shared, replica_id="replica-a") as (api, a):
        assert a.office_lease is not None and a.office_lease.lease is not None
        first = a.office_lease.lease
        replica = (await api.get("/readyz")).json()["replica"]
        assert (replica["id"], replica["fencing_token"]) == ("replica-a", first.token)
        office = a.office.name
        assert await lease_series(api) == {
            f'assistantx_office_lease_token{{office="{office}",replica="replica-a"}}': first.token,
            'assistantx_replica_ready{replica="replica-a"}': 1.0,
        }
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
    # /metrics on the new holder names it, with the next token: a failover shows as a change.
    assert seen["metrics"] == {
        f'assistantx_office_lease_token{{office="{office}",replica="replica-b"}}': first.token + 1,
        'assistantx_replica_ready{replica="replica-b"}': 1.0,
    }


async def lease_series(api: httpx.AsyncClient) -> dict[str, float]:
    """The lease token and readiness series of ``/metrics`` (the expiry moves; it is only
    checked to be there and in the future)."""
    text = (await api.get("/metrics", headers={"Authorization": f"Bearer {OPERATOR}"})).text
    series: dict[str, float] = {}
    for line in text.splitlines():
        name, _, value = line.rpartition(" ")
        if name.startswith("assistantx_office_lease_expires_in_seconds{"):
            assert 0 < float(value) <= TTL_S, line
        elif name.startswith(("assistantx_office_lease_token{", "assistantx_replica_ready{")):
            series[name] = float(value)
    return series


def _standby(tmp_path: Path, env: dict[str, str]) -> tuple[subprocess.Popen[bytes], int, Path]:
    """Replica B as a real ``assistantx serve`` process (started after A, so it waits as the
    standby): the process, its port and its log."""
    port = free_port()
    log = tmp_path / "b.log"
    command = [sys.executable, "-m", "assistantx", "serve", "--port", str(port)]
    b_env = base_env(tmp_path / "b", ASSISTANTX_REPLICA_ID="replica-b", **env)
    with log.open("wb") as out:
        process = subprocess.Popen(command, env=b_env, stdout=out, stderr=subprocess.STDOUT)
    return process, port, log


def _stop(process: subprocess.Popen[bytes]) -> None:
    if process.poll() is None:
        process.terminate()
        process.wait(20)


@pytest.mark.slow
def test_a_killed_replica_is_replaced_by_the_standby_within_the_lease(
    tmp_path: Path, postgres_url: str
) -> None:
    """Two real ``assistantx serve`` processes: kill -9 the one that runs the office while
    an instruction waits for a colleague; the standby is ready within the lease's time (plus
    its own start) and runs the instruction on."""
    env = {
        "ASSISTANTX_DATABASE_URL": postgres_url,
        "ASSISTANTX_LEASE_TTL_S": "2",
        "ASSISTANTX_LOCK_SHARED_KEY": "the replicas' shared lock key for the tests",
        "ASSISTANTX_ROBOT": "sim",
        "ASSISTANTX_SIM_HANDOVER_DELAY_S": "3600",
    }
    a = serve(tmp_path / "a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    b, b_port, b_log = _standby(tmp_path, env)
    try:
        headers = {"Authorization": f"Bearer {OPERATOR}"}
        with httpx.Client(base_url=a.url, headers=headers, timeout=10) as api:
            iid = submit_stapler(api, headers)
        eventually_sync(
            b_log.read_text,
            until=lambda log: "waiting as a standby" in log,
            what="replica B to wait as a standby",
        )
        assert b.poll() is None
        a.kill()  # SIGKILL: no shutdown, no release; the lease expires
        killed = time.monotonic()
        wait_ready(b, f"http://127.0.0.1:{b_port}/readyz", timeout_s=60)
        took = time.monotonic() - killed
        with httpx.Client(base_url=f"http://127.0.0.1:{b_port}", headers=headers) as api:
            record = api.get(f"/v1/instructions/{iid}").json()
        assert record["status"] in ("queued", "running"), record
        assert "taken over by this replica" in b_log.read_text()
        assert took < 30, f"the standby took {took:.1f} s"
    finally:
        a.stop()
        _stop(b)


def journal_rows(url: str, sql: str) -> list[tuple[Any, ...]]:
    with psycopg.connect(url, autocommit=True) as db:
        return list(db.execute(sql).fetchall())


@pytest.mark.slow
def test_no_message_or_code_goes_out_twice_across_a_failover(
    tmp_path: Path, postgres_url: str
) -> None:
    """kill -9 the holder while a simulated colleague is being asked: the standby takes the
    instruction over and ends it, and every message and code of it went out exactly once
    (the shared journal is the count: a resend would be a second row or a second result)."""
    env = {
        "ASSISTANTX_DATABASE_URL": postgres_url,
        "ASSISTANTX_LEASE_TTL_S": "2",
        "ASSISTANTX_LOCK_SHARED_KEY": "the replicas' shared lock key for the tests",
        "ASSISTANTX_ROBOT": "sim",
        "ASSISTANTX_SIM_REPLY_DELAY_S": "60",  # 1.2 s here; 300 times the question out
        "ASSISTANTX_SIM_HANDOVER_DELAY_S": "10",
    }
    a = serve(tmp_path / "a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    b, b_port, b_log = _standby(tmp_path, env)
    headers = {"Authorization": f"Bearer {OPERATOR}"}
    try:
        eventually_sync(
            b_log.read_text,
            until=lambda log: "waiting as a standby" in log,
            what="replica B to wait as a standby",
            timeout_s=60,
        )
        with httpx.Client(base_url=a.url, headers=headers, timeout=10) as api:
            iid = submit_stapler(api, headers)
        eventually_sync(
            lambda: journal_rows(
                postgres_url,
                "SELECT count(*) FROM messages WHERE direction='out' AND question_id IS NOT NULL",
            )[0][0],
            until=lambda asked: asked > 0,
            what="replica A to ask a colleague",
            timeout_s=60,
        )
        a.kill()  # SIGKILL while the colleague's answer is pending
        answers = "SELECT count(*) FROM messages WHERE direction='in'"
        assert journal_rows(postgres_url, answers) == [(0,)]  # the kill came before the answer
        wait_ready(b, f"http://127.0.0.1:{b_port}/readyz", timeout_s=60)
        record = eventually_sync(
            lambda: httpx.get(
                f"http://127.0.0.1:{b_port}/v1/instructions/{iid}", headers=headers
            ).json(),
            until=lambda r: r["status"] not in ("queued", "running"),
            what="the instruction to end on replica B",
            timeout_s=120,
        )
        assert record["status"] == "done", record
        repeated = journal_rows(
            postgres_url,
            "SELECT chat_id, text, count(*) FROM messages WHERE direction='out'"
            " GROUP BY chat_id, text HAVING count(*) > 1",
        )
        assert repeated == []
        assert journal_rows(postgres_url, answers)[0][0] > 0  # B heard the colleague's answer
        asked = "SELECT chat_id FROM messages WHERE direction='out' AND question_id IS NOT NULL"
        assert journal_rows(postgres_url, asked) == [("wang",)]  # asked by A, not again by B
        codes = journal_rows(
            postgres_url,
            "SELECT data FROM events WHERE kind='action_result' AND data LIKE '%send_qr%'",
        )
        sent = [json.loads(d)["result"] for (d,) in codes]
        to = [s["action"]["contact"] for s in sent if s["ok"]]
        assert to and len(to) == len(set(to)), sent  # one code to each person, never a second
    finally:
        a.stop()
        _stop(b)
