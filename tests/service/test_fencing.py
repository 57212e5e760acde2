"""Two real replicas on the tests' PostgreSQL: a replica that lost its lease while paused
cannot write when it wakes (fencing), and a clean shutdown (SIGTERM) hands the office over
at once instead of letting the lease run out."""

from __future__ import annotations

import signal
from pathlib import Path

import httpx
import pytest

from helpers.eventually import eventually_sync
from helpers.processes import wait_ready
from service.server import OPERATOR, free_port, serve
from service.standby import rows, start_standby

pytestmark = [pytest.mark.postgres, pytest.mark.slow]

HEADERS = {"Authorization": f"Bearer {OPERATOR}"}
SHARED = {"ASSISTANTX_LOCK_SHARED_KEY": "the replicas' shared lock key for the tests"}


def test_a_paused_replica_that_lost_its_lease_cannot_write_when_it_wakes(
    tmp_path: Path, postgres_url: str
) -> None:
    env = {"ASSISTANTX_DATABASE_URL": postgres_url, "ASSISTANTX_LEASE_TTL_S": "2", **SHARED}
    a = serve(tmp_path / "a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    b = start_standby(tmp_path, "replica-b", env)
    try:
        a.process.send_signal(signal.SIGSTOP)  # a long GC, a stopped VM: it knows nothing
        wait_ready(b.process, f"{b.url}/readyz", timeout_s=60)
        assert rows(postgres_url, "SELECT holder, token FROM leases") == [("replica-b", 2)]
        a.process.send_signal(signal.SIGCONT)
        # A still believes it runs the office: a submission to it must not reach the journal.
        try:
            r = httpx.post(
                f"{a.url}/v1/instructions",
                headers=HEADERS,
                json={"requester": "lee", "text": "Please bring me a pen."},
                timeout=10,
            )
            assert r.status_code != 202, r.text
        except httpx.HTTPError:
            pass  # it noticed first and is stopping: refused as well
        a.process.wait(30)  # it stops itself once it sees the lease lost
        assert "lost its lease" in a.log.read_text()
        assert rows(
            postgres_url, "SELECT count(*) FROM instructions WHERE text = 'Please bring me a pen.'"
        ) == [(0,)]
        assert rows(postgres_url, "SELECT holder, token FROM leases") == [("replica-b", 2)]
        assert httpx.get(f"{b.url}/readyz").status_code == 200
    finally:
        if a.process.poll() is None:
            a.process.send_signal(signal.SIGCONT)  # a paused process does not hear SIGTERM
        a.stop()
        b.stop()


def test_a_clean_shutdown_hands_the_office_over_before_its_lease_runs_out(
    tmp_path: Path, postgres_url: str
) -> None:
    """A lease of 15 s: a standby that took it before it ran out got it from the release
    (standbys try every third of the lease)."""
    env = {"ASSISTANTX_DATABASE_URL": postgres_url, "ASSISTANTX_LEASE_TTL_S": "15", **SHARED}
    a = serve(tmp_path / "a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    b = start_standby(tmp_path, "replica-b", env)
    try:
        ((expires_at,),) = rows(postgres_url, "SELECT expires_at FROM leases")
        a.process.send_signal(signal.SIGTERM)
        # uvicorn shuts down cleanly, then ends by the signal it was sent
        assert a.process.wait(30) in (0, -signal.SIGTERM)
        assert "Application shutdown complete" in a.log.read_text()
        ((holder, _),) = rows(postgres_url, "SELECT holder, expires_at FROM leases")
        assert holder in ("", "replica-b")  # released ("") or already taken
        ((holder, token, now),) = eventually_sync(
            lambda: rows(
                postgres_url, "SELECT holder, token, extract(epoch FROM now()) FROM leases"
            ),
            until=lambda found: found[0][0] == "replica-b",
            what="replica B to take the office",
        )
        assert token == 2
        assert float(now) < expires_at  # A's own lease had not run out
        wait_ready(b.process, f"{b.url}/readyz", timeout_s=60)
    finally:
        a.stop()
        b.stop()
