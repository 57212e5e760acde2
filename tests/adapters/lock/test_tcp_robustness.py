"""Hostile and broken peers: garbage, oversized frames, slowloris, half-open connections."""

from __future__ import annotations

import asyncio
import contextlib
import random
import struct
import time

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.protocol.frames import encode_frame, encode_message
from assistantx.adapters.lock.protocol.link import client_handshake, close_writer
from assistantx.core.clock import SimClock
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer

from .conftest import FAST, LOCK_ID, tcp_locker

Attack = tuple[str, bytes | None, float]  # name, bytes to send, pause between bytes (s)


async def _read_until_closed(reader: asyncio.StreamReader, limit_s: float) -> float:
    """Seconds until the lock hung up on us. A hang-up may come as a reset: a server that
    closes a socket with our unread garbage still in its buffer sends RST, not FIN, and the
    read then fails with ConnectionResetError (seen once in CI); that is hanging up too."""
    started = time.monotonic()
    async with asyncio.timeout(limit_s):
        with contextlib.suppress(ConnectionResetError):
            while await reader.read(4096):
                pass
    return time.monotonic() - started


async def _attack(port: int, payload: bytes | None, pause_s: float) -> float:
    reader, writer = await asyncio.open_connection("127.0.0.1", port)
    try:
        if payload is None:  # connect, then reset straight away
            writer.transport.abort()
            return 0.0
        if pause_s:
            sender = asyncio.create_task(_trickle(writer, payload, pause_s))
            try:
                return await _read_until_closed(reader, 3.0)
            finally:
                sender.cancel()
        writer.write(payload)
        return await _read_until_closed(reader, 3.0)
    finally:
        await close_writer(writer)


async def _trickle(writer: asyncio.StreamWriter, payload: bytes, pause_s: float) -> None:
    for byte in payload:
        writer.write(bytes([byte]))
        await writer.drain()
        await asyncio.sleep(pause_s)


async def _authenticated_then(port: int, keys: LockKeys, payload: bytes) -> float:
    reader, writer = await asyncio.open_connection("127.0.0.1", port)
    try:
        await client_handshake(reader, writer, link_key=keys.link_key, handshake_s=1.0)
        writer.write(payload)
        return await _read_until_closed(reader, 3.0)
    finally:
        await close_writer(writer)


async def test_the_emulator_survives_a_garbage_and_slowloris_storm(
    keys: LockKeys, clock: SimClock
) -> None:
    rng = random.Random(7)
    controller = LockController(LOCK_ID, keys.codes, clock)
    # Room for every attacker at once, so each one meets its own timeout (eviction of the
    # oldest unauthenticated connections is tested in test_tcp_flood).
    server = LockServer(
        controller, keys.link_key, timeouts=FAST, max_connections=64, max_pending_per_peer=64
    )
    _, port = await server.start()
    auth_frame = encode_frame(encode_message({"type": "auth", "version": 1, "nonce": "x" * 22}))
    attacks: list[Attack] = [
        *[("garbage", rng.randbytes(2048), 0.0) for _ in range(8)],
        *[("oversized", struct.pack(">I", 2**31) + b"x" * 100, 0.0) for _ in range(4)],
        *[("silent", b"", 0.0) for _ in range(4)],
        *[("slowloris", auth_frame, 0.05) for _ in range(4)],
        *[("reset", None, 0.0) for _ in range(4)],
        *[("not json", encode_frame(b"\xff\xfe{{{"), 0.0) for _ in range(2)],
    ]
    try:
        async with tcp_locker(server, keys, clock) as locker:
            storm = [asyncio.create_task(_attack(port, data, pause)) for _, data, pause in attacks]
            storm += [
                # Past the handshake: a frame with a bad MAC, an oversized one, then silence.
                asyncio.create_task(_authenticated_then(port, keys, encode_frame(b"\x00" * 40))),
                asyncio.create_task(_authenticated_then(port, keys, struct.pack(">I", 2**30))),
                asyncio.create_task(_authenticated_then(port, keys, b"")),
            ]
            # The rightful assistant works through the storm.
            qr = await locker.issue_code(
                instruction_id="i", person="lee", purpose="deposit", item="x"
            )
            assert (await locker.simulate_scan(qr.payload)).kind == "code_accepted"
            assert (await locker.simulate_close()).person == "lee"

            hang_ups = await asyncio.gather(*storm)
            # Every attacker was cut off by a timeout or a check, none held on for long.
            assert max(hang_ups) < 2.5
            silent_at = [i for i, (name, _, _) in enumerate(attacks) if name == "silent"]
            assert all(hang_ups[i] >= FAST.handshake_s * 0.9 for i in silent_at)
            assert hang_ups[-1] >= FAST.idle_s * 0.9  # the silent authenticated peer
            assert server.refused_handshakes >= len(attacks) - 4

            assert (await locker.status()).door == "closed"
            assert locker.client.connections == 1
            assert server.connection_count == 1
    finally:
        await server.stop()


async def test_sessions_beyond_the_limit_are_turned_away(keys: LockKeys, clock: SimClock) -> None:
    """``max_connections`` bounds authenticated sessions: a third client that proves the key
    is hung up on at once; unauthenticated sockets do not count against it."""
    controller = LockController(LOCK_ID, keys.codes, clock)
    server = LockServer(controller, keys.link_key, timeouts=FAST, max_connections=2)
    _, port = await server.start()
    try:
        idle = [await asyncio.open_connection("127.0.0.1", port) for _ in range(4)]
        held = []
        for _ in range(2):
            reader, writer = await asyncio.open_connection("127.0.0.1", port)
            await client_handshake(reader, writer, link_key=keys.link_key, handshake_s=1.0)
            held.append((reader, writer))
        reader, writer = await asyncio.open_connection("127.0.0.1", port)
        await client_handshake(reader, writer, link_key=keys.link_key, handshake_s=1.0)
        assert await _read_until_closed(reader, 0.4) < 0.3  # turned away at once
        assert server.session_count == 2
        await close_writer(writer)
        for _, held_writer in [*held, *idle]:
            await close_writer(held_writer)
    finally:
        await server.stop()
