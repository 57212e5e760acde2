"""A standby replica of one office (no deployment file) answers HTTP while another holds the
office: health, who holds the office (``/readyz``, ``/v1/offices``, ``/metrics``), reads and
submissions from the shared journal; once the holder shuts down cleanly it takes the office
over and resumes what was submitted through it."""

from __future__ import annotations

from pathlib import Path

import httpx
import pytest

from helpers.eventually import eventually_sync
from helpers.processes import wait_ready
from service.server import OPERATOR, free_port, serve
from service.standby import start_standby

pytestmark = [pytest.mark.postgres, pytest.mark.slow]

HEADERS = {"Authorization": f"Bearer {OPERATOR}"}
ENV = {
    "ASSISTANTX_LOCK_SHARED_KEY": "the replicas' shared lock key for the tests",
    "ASSISTANTX_LEASE_TTL_S": "2",
    "ASSISTANTX_ROBOT": "sim",
    # Wang takes a simulated hour to come: the instruction is still running at the handover.
    "ASSISTANTX_SIM_HANDOVER_DELAY_S": "3600",
}


def series(text: str, name: str) -> dict[str, float]:
    """The samples of one metric family, by their label text."""
    found: dict[str, float] = {}
    for line in text.splitlines():
        if line.startswith(name + "{"):
            labels, _, value = line[len(name) :].rpartition(" ")
            found[labels] = float(value)
    return found


def test_a_standby_serves_health_reads_and_submissions_then_takes_over(
    tmp_path: Path, postgres_url: str
) -> None:
    env = {**ENV, "ASSISTANTX_DATABASE_URL": postgres_url}
    a = serve(tmp_path / "replica-a", free_port(), ASSISTANTX_REPLICA_ID="replica-a", **env)
    b = start_standby(tmp_path, "replica-b", env)
    try:
        with httpx.Client(base_url=b.url, headers=HEADERS, timeout=10) as standby:
            assert standby.get("/healthz").json() == {"status": "ok"}
            ready = standby.get("/readyz")
            assert ready.status_code == 503
            assert ready.json() == {
                "status": "standby",
                "replica": "replica-b",
                "holder": "replica-a",
            }
            [office] = standby.get("/v1/offices").json()
            assert (office["replica"], office["here"], office["status"]) == (
                "replica-a",
                False,
                "elsewhere",
            )
            metrics = standby.get("/metrics")
            assert metrics.status_code == 200, metrics.text
            assert series(metrics.text, "assistantx_office_replica") == {
                '{office="default",replica="replica-a"}': 1.0
            }
            assert series(metrics.text, "assistantx_replica_up") == {
                '{replica="replica-a"}': 1.0,
                '{replica="replica-b"}': 1.0,
            }
            stranger = {"Authorization": "Bearer not-a-token-of-this-office"}
            assert standby.get("/metrics", headers=stranger).status_code == 401

            # A submission through the standby is journaled and run by the holder.
            r = standby.post(
                "/v1/instructions", json={"requester": "lee", "text": "Please bring me a stapler."}
            )
            assert r.status_code == 202, r.text
            iid = r.json()["id"]
            assert standby.get(f"/v1/instructions/{iid}").status_code == 200
            with httpx.Client(base_url=a.url, headers=HEADERS, timeout=10) as holder:
                eventually_sync(
                    lambda: holder.get(f"/v1/instructions/{iid}").json()["status"],
                    until=lambda status: status == "running",
                    what="the holder to run the instruction submitted through the standby",
                    timeout_s=60,
                )
                holder_metrics = holder.get("/metrics").text
            assert series(holder_metrics, "assistantx_office_replica") == {
                '{office="default",replica="replica-a"}': 1.0
            }

            # A clean shutdown hands the office to the standby, which resumes the instruction.
            a.stop()
            wait_ready(b.process, f"{b.url}/readyz", timeout_s=60)
            ready = standby.get("/readyz").json()
            assert ready["replica"]["id"] == "replica-b"
            assert iid in ready["resumed"]
            assert standby.get(f"/v1/instructions/{iid}").json()["status"] == "running"
    finally:
        a.stop()
        b.stop()
