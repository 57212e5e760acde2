"""Two offices over two real replica processes on the tests' PostgreSQL, one office each:
either replica answers reads of both offices from the shared journal, and a submission to
the replica that does not run the office is journaled there and started by the one that
does (told through LISTEN/NOTIFY on the office's channel)."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import httpx
import pytest

from helpers.eventually import eventually_sync
from service.replicas import deployment, replica
from service.server import OPERATOR, Server
from service.standby import holders

pytestmark = [pytest.mark.postgres, pytest.mark.slow]

HEADERS = {"Authorization": f"Bearer {OPERATOR}"}


def _replica(folder: Path, name: str, url: str, offices: Path) -> Server:
    return replica(folder, name, url, offices, ASSISTANTX_LEASE_TTL_S="2", ASSISTANTX_SPEEDUP="50")


def test_a_replica_takes_submissions_and_reads_for_an_office_another_runs(
    tmp_path: Path, postgres_url: str
) -> None:
    offices = deployment(tmp_path, "hq", "harbour")
    a = _replica(tmp_path, "replica-a", postgres_url, offices)
    b: Server | None = None
    try:
        b = _replica(tmp_path, "replica-b", postgres_url, offices)
        view = eventually_sync(
            lambda: holders(a),
            until=lambda v: (
                None not in v.values()
                and sorted(Counter(v.values()).values()) == [1, 1]
                and holders(b) == v
            ),
            what="one office on each replica",
            timeout_s=90,
        )
        by_name = {"replica-a": a, "replica-b": b}
        for office, owner_name in view.items():
            other = b if owner_name == "replica-a" else a
            owner = by_name[owner_name]
            base = f"/v1/offices/{office}/instructions"
            # Before this, the replica that does not run the office answered 503.
            r = httpx.post(
                f"{other.url}{base}",
                headers=HEADERS,
                json={
                    "requester": "lee" if office == "hq" else "will",
                    "text": "Please tell me the time.",
                },
                timeout=10,
            )
            assert r.status_code == 202, r.text
            iid = r.json()["id"]
            # Started by the owner (it was told), read on both, from the one journal.
            ended = eventually_sync(
                lambda url=other.url, path=f"{base}/{iid}": httpx.get(
                    f"{url}{path}", headers=HEADERS, timeout=10
                ).json(),
                until=lambda rec: rec.get("status") not in (None, "queued", "running"),
                what=f"the instruction submitted to {office} through the other replica to end",
                timeout_s=90,
            )
            assert ended["trace"]["steps"], ended  # run by a reasoner, not just journaled
            on_owner = httpx.get(f"{owner.url}{base}/{iid}", headers=HEADERS, timeout=10).json()
            assert on_owner["status"] == ended["status"]
            listed = httpx.get(f"{other.url}{base}", headers=HEADERS, timeout=10).json()
            assert [item["id"] for item in listed["items"]] == [iid]
    finally:
        for server in (a, b):
            if server is not None:
                server.stop()
