"""A burst of concurrent POSTs to the real server: every one is answered 202, and every
instruction so acknowledged is in the journal the moment its answer leaves (a kill -9 right
after the last answer loses none of them: the restarted service reads and resumes each one,
with the text that was sent)."""

from __future__ import annotations

import asyncio
from pathlib import Path

import httpx
import pytest

from service.server import LEE, OPERATOR, free_port, serve

# Starts processes: not in `make test-fast`.
pytestmark = pytest.mark.slow

BURST = 40
UNLIMITED = {"ASSISTANTX_INSTRUCTIONS_PER_MINUTE": "0"}  # one person sends the whole burst
AUTH_LEE = {"Authorization": f"Bearer {LEE}"}
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}


async def _burst(url: str) -> dict[str, str]:
    """POST ``BURST`` instructions at once; {id: text} of those answered 202 (all, asserted)."""
    limits = httpx.Limits(max_connections=BURST, max_keepalive_connections=BURST)
    async with httpx.AsyncClient(base_url=url, limits=limits, timeout=60) as client:

        async def post(n: int) -> tuple[int, str, str]:
            text = f"Please bring me a stapler, number {n}."
            r = await client.post(
                "/v1/instructions", json={"requester": "lee", "text": text}, headers=AUTH_LEE
            )
            return r.status_code, str(r.json().get("id")), text

        answers = await asyncio.gather(*(post(n) for n in range(BURST)))
    assert [status for status, _, _ in answers] == [202] * BURST, answers
    return {iid: text for _, iid, text in answers}


def test_every_answered_post_of_a_burst_survives_kill_9(tmp_path: Path) -> None:
    port = free_port()
    server = serve(tmp_path / "data", port, **UNLIMITED)
    try:
        accepted = asyncio.run(_burst(server.url))
    finally:
        server.kill()  # at once: nothing after the last answer had time to run
    assert len(accepted) == BURST  # distinct ids

    server = serve(tmp_path / "data", port, **UNLIMITED)
    try:
        with httpx.Client(base_url=server.url, timeout=30) as client:
            for iid, text in accepted.items():
                r = client.get(f"/v1/instructions/{iid}", headers=AUTH_OP)
                assert r.status_code == 200, (iid, r.text)
                assert r.json()["text"] == text and r.json()["requester"] == "lee"
            resumed = set(client.get("/readyz").json()["resumed"])
            listed = client.get("/v1/instructions?limit=200", headers=AUTH_OP).json()["items"]
            ended = {i["id"] for i in listed if i["status"] not in ("queued", "running")}
            assert set(accepted) <= resumed | ended  # each one started again or had ended
    finally:
        server.stop()
