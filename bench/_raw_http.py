"""A lean HTTP/1.1 client for the load bench's burst: connections opened beforehand, each
request written as prepared bytes and its answer read with the least parsing.

Why: on the 2-core machine the bench's httpx client spent as much CPU on a burst of 200 POSTs
as the service did to answer them (0.5-1.2 CPU-s against 0.2-1.4 s, ``burst_client_cpu_s``),
on the same cores, so the burst's latencies measured the client as much as the service. Here
the client's share is a write and a read per request; the connections are those of 200
clients already connected (as the load phase's clients are), so the burst measures answering,
not TCP set-up or the client's request building.
"""

from __future__ import annotations

import asyncio
import json
import time
from typing import Any


class RawConnections:
    """``n`` kept-alive connections to ``host:port``; ``post_all`` sends one POST on each at
    once. Used as an async context (the connections are closed on exit)."""

    def __init__(self, host: str, port: int, n: int) -> None:
        self.host, self.port, self.n = host, port, n
        self._streams: list[tuple[asyncio.StreamReader, asyncio.StreamWriter]] = []

    async def __aenter__(self) -> RawConnections:
        self._streams = list(
            await asyncio.gather(
                *(asyncio.open_connection(self.host, self.port) for _ in range(self.n))
            )
        )
        return self

    async def __aexit__(self, *exc_info: object) -> None:
        for _, writer in self._streams:
            writer.close()
        await asyncio.gather(*(w.wait_closed() for _, w in self._streams), return_exceptions=True)

    def request(self, path: str, body: dict[str, Any], token: str) -> bytes:
        """A POST of ``body`` as JSON, ready to write."""
        data = json.dumps(body).encode()
        head = (
            f"POST {path} HTTP/1.1\r\nHost: {self.host}:{self.port}\r\n"
            f"Authorization: Bearer {token}\r\nContent-Type: application/json\r\n"
            f"Content-Length: {len(data)}\r\n\r\n"
        )
        return head.encode() + data

    async def post_all(self, requests: list[bytes]) -> list[tuple[float, int, bytes]]:
        """Each request on its own connection, all at once: (seconds from its write to the
        end of its answer, status, body) in order."""
        streams = self._streams[: len(requests)]
        exchanges = [_exchange(r, w, req) for (r, w), req in zip(streams, requests, strict=True)]
        return list(await asyncio.gather(*exchanges))


async def _exchange(
    reader: asyncio.StreamReader, writer: asyncio.StreamWriter, request: bytes
) -> tuple[float, int, bytes]:
    t0 = time.perf_counter()
    writer.write(request)
    head = await reader.readuntil(b"\r\n\r\n")
    lines = head.split(b"\r\n")
    status = int(lines[0].split()[1])
    length = 0
    for line in lines[1:]:
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            length = int(value)
    body = await reader.readexactly(length)
    return time.perf_counter() - t0, status, body
