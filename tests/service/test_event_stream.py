"""The live event stream as a client reads it: text/event-stream with no caching, keep-alive
comments while nothing happens, and a person's token sees only their own instructions."""

from __future__ import annotations

import asyncio
import contextlib
import json
from collections.abc import Callable

import httpx
import pytest

from service.server import LEE, OPERATOR, ZHANG

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}
AS_ZHANG = {"Authorization": f"Bearer {ZHANG}"}


async def _read(
    api: httpx.AsyncClient,
    path: str,
    headers: dict[str, str],
    seconds: float,
    enough: Callable[[list[str]], bool] = lambda _: True,
    limit_s: float = 30.0,
) -> tuple[httpx.Headers, list[str]]:
    """The response headers and the lines the stream sent in ``seconds``, and after that
    until the lines are ``enough`` (up to ``limit_s`` more: on a loaded machine the events a
    test waits for came after a fixed window had closed)."""
    lines: list[str] = []
    got: list[httpx.Headers] = []
    satisfied = asyncio.Event()

    async def read() -> None:
        async with api.stream("GET", path, headers=headers) as response:
            assert response.status_code == 200
            got.append(response.headers)
            async for line in response.aiter_lines():
                lines.append(line)
                if enough(lines):
                    satisfied.set()

    reading = asyncio.create_task(read())
    waiting = asyncio.create_task(satisfied.wait())
    try:
        await asyncio.wait({reading}, timeout=seconds)
        if not reading.done() and not enough(lines):
            await asyncio.wait(
                {reading, waiting}, timeout=limit_s, return_when=asyncio.FIRST_COMPLETED
            )
    finally:
        waiting.cancel()
        reading.cancel()
        with contextlib.suppress(asyncio.CancelledError):
            await reading  # an assertion inside the reader is raised here
    assert got, "the stream never answered"
    return got[0], lines


async def test_an_idle_stream_sends_keep_alive_comments(
    api: httpx.AsyncClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    # FastAPI's SSE response sends the keep-alives; its interval (15 s) is shortened here so
    # that a second of silence shows several. Renaming it upstream fails this test loudly.
    # Read until three have come (a fixed second saw two on a loaded machine).
    monkeypatch.setattr("fastapi.routing._PING_INTERVAL", 0.2)

    def three_comments(lines: list[str]) -> bool:
        return sum(line.startswith(":") for line in lines) >= 3

    headers, lines = await _read(api, "/v1/events", OP, 0, enough=three_comments)
    assert headers["content-type"].startswith("text/event-stream")
    assert headers["cache-control"] == "no-cache"
    assert headers["x-accel-buffering"] == "no"  # a proxy must not hold events back
    comments = [line for line in lines if line.startswith(":")]
    assert len(comments) >= 3, lines
    assert all(line.startswith(":") or line == "" for line in lines), lines  # nothing else


async def test_a_person_follows_only_their_own_instructions(api: httpx.AsyncClient) -> None:
    ids = {}
    for person, auth in (("lee", AS_LEE), ("zhang", AS_ZHANG)):
        body = {"requester": person, "text": "Bring me a stapler"}
        created = await api.post("/v1/instructions", json=body, headers=auth)
        assert created.status_code == 202, created.text
        ids[person] = created.json()["id"]

    def events(lines: list[str]) -> list[tuple[str, str, dict[str, object]]]:
        """(id, event, data) per event; every event carries all three fields."""
        out, fields = [], {}
        for line in lines:
            if line == "":
                if fields:
                    out.append((fields["id"], fields["event"], json.loads(fields["data"])))
                fields = {}
            elif not line.startswith(":"):
                name, _, value = line.partition(": ")
                fields[name] = value
        return out

    def ids_seen(lines: list[str]) -> set[object]:
        return {data["instruction_id"] for _, _, data in events(lines)}

    # The operator's stream: until both instructions have shown.
    everyone = set(ids.values())
    _, everything = await _read(
        api, "/v1/events", OP, 0, enough=lambda lines: ids_seen(lines) >= everyone
    )
    assert ids_seen(everything) == everyone
    zhangs = [
        int(seq) for seq, _, data in events(everything) if data["instruction_id"] == ids["zhang"]
    ]

    def past_one_of_zhangs(lines: list[str]) -> bool:
        """Two of the events read lie on either side of one of Zhang's in the journal: the
        stream had that event in hand, and left it out if all were Lee's."""
        seqs = [int(seq) for seq, _, _ in events(lines)]
        return bool(seqs) and any(min(seqs) < z < max(seqs) for z in zhangs)

    # Lee's stream: until it is past one of Zhang's events (a fixed 1.5 s window stood in
    # for this, time in which another person's events would have shown).
    _, lines = await _read(api, "/v1/events", AS_LEE, 0, enough=past_one_of_zhangs)
    assert past_one_of_zhangs(lines), lines
    seen = events(lines)
    assert seen and {data["instruction_id"] for _, _, data in seen} == {ids["lee"]}
    assert all(kind == data["kind"] for _, kind, data in seen)
    seqs = [int(seq) for seq, _, _ in seen]
    assert seqs == sorted(set(seqs))  # journal order, no repeats
