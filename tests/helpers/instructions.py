"""Waiting for an instruction of the service to end, through its event stream."""

from __future__ import annotations

import asyncio
from typing import Any

import httpx

ACTIVE = ("queued", "running")


def submit_stapler(client: httpx.Client, headers: dict[str, str]) -> str:
    """Lee asks the service for a stapler; the new instruction's id (202 asserted)."""
    r = client.post(
        "/v1/instructions",
        json={"requester": "lee", "text": "Please bring me a stapler."},
        headers=headers,
    )
    assert r.status_code == 202, r.text
    assert r.headers["location"] == f"/v1/instructions/{r.json()['id']}"
    return str(r.json()["id"])


async def ended(
    client: httpx.AsyncClient,
    iid: str,
    headers: dict[str, str] | None = None,
    *,
    timeout_s: float = 60.0,
) -> dict[str, Any]:
    """The instruction's record once it has ended (done, failed, cancelled...).

    Follows ``/v1/instructions/{iid}/events``, which ends after the instruction's
    ``instruction_ended`` event (journaled, with the final status, before it is sent); a stream
    the server drops early is resumed from its last id."""
    try:
        async with asyncio.timeout(timeout_s):
            return await _follow_to_end(client, iid, headers)
    except TimeoutError:
        raise AssertionError(f"instruction {iid} did not end within {timeout_s:g} s") from None


async def _follow_to_end(
    client: httpx.AsyncClient, iid: str, headers: dict[str, str] | None
) -> dict[str, Any]:
    path = f"/v1/instructions/{iid}"
    last = ""
    while True:
        resume = {"Last-Event-ID": last} if last else {}
        # A connection of its own: the stream's does not go back to the client's pool.
        async with (
            httpx.AsyncClient(
                base_url=client.base_url, headers=client.headers, timeout=None
            ) as own,
            own.stream("GET", f"{path}/events", headers={**(headers or {}), **resume}) as response,
        ):
            assert response.status_code == 200, await response.aread()
            async for line in response.aiter_lines():
                if line.startswith("id: "):
                    last = line[4:]
            # On this fresh connection too: the client's pooled one has idled through the
            # whole instruction, past the server's keep-alive, and may be closing under us.
            body: dict[str, Any] = (await own.get(path, headers=headers)).json()
        if body["status"] not in ACTIVE:
            return body
