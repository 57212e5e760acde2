"""Hand-overs through the real TCP link: TcpLocker -> 127.0.0.1 -> LockServer."""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest

from assistantx.adapters.lock.protocol import CodeIssuer, Keyring, LockKeys
from assistantx.adapters.lock.protocol.frames import encode_frame, encode_message
from assistantx.adapters.lock.protocol.keys import b64encode, new_key
from assistantx.adapters.lock.protocol.link import client_handshake, close_writer
from assistantx.core.clock import SimClock
from assistantx.core.errors import (
    InvalidCodeError,
    LockAuthError,
    LockCommandError,
    LockProtocolError,
)
from assistantx.core.ports.lock import LockEvent
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from helpers.eventually import assert_quiet

from .conftest import FAST, LOCK_ID, tcp_locker


async def _next_events(queue: asyncio.Queue[LockEvent], count: int) -> list[LockEvent]:
    async with asyncio.timeout(2):
        return [await queue.get() for _ in range(count)]


async def test_full_hand_over_is_attributed_and_reported_once(
    server: LockServer, keys: LockKeys, clock: SimClock
) -> None:
    async with tcp_locker(server, keys, clock, render_png=True) as locker:
        events = locker.subscribe()
        qr = await locker.issue_code(
            instruction_id="ins-9", person="lee", purpose="deposit", item="document:lee"
        )
        assert qr.png is not None
        assert qr.png.startswith(b"\x89PNG")
        assert (await locker.status()).active_codes == 1

        accepted = await locker.simulate_scan(qr.payload)
        assert (accepted.kind, accepted.person, accepted.code_id) == (
            "code_accepted",
            "lee",
            qr.code_id,
        )
        status = await locker.status()
        assert (status.door, status.locked) == ("open", False)
        closed = await locker.simulate_close()
        assert (closed.kind, closed.person, closed.instruction_id) == (
            "door_closed",
            "lee",
            "ins-9",
        )

        pushed = await _next_events(events, 3)
        assert [(e.seq, e.kind, e.person) for e in pushed] == [
            (1, "code_accepted", "lee"),
            (2, "door_opened", "lee"),
            (3, "door_closed", "lee"),
        ]
        status = await locker.status()
        assert (status.door, status.locked, status.contents) == ("closed", True, ["document:lee"])
        await assert_quiet(events, 0.05, what="event after the hand-over")


async def test_replayed_expired_forged_and_other_lock_codes_are_rejected(
    server: LockServer, keys: LockKeys, clock: SimClock
) -> None:
    async with tcp_locker(server, keys, clock) as locker:
        used = await locker.issue_code(
            instruction_id="i", person="lee", purpose="collect", item="x"
        )
        assert (await locker.simulate_scan(used.payload)).kind == "code_accepted"
        await locker.simulate_close()
        replay = await locker.simulate_scan(used.payload)
        assert (replay.kind, replay.reason) == ("code_rejected", "replayed")

        late = await locker.issue_code(
            instruction_id="i", person="lee", purpose="collect", item="x"
        )
        clock.advance(601)
        assert (await locker.simulate_scan(late.payload)).reason == "expired"

        forger = CodeIssuer(LOCK_ID, Keyring.single("k0", new_key()), clock, render=False)
        _, forged = forger.issue(instruction_id="i", person="eve", purpose="collect", item="x")
        assert (await locker.simulate_scan(forged)).reason == "forged"
        with pytest.raises(InvalidCodeError) as caught:
            await locker.client.request("provision", payload=forged)
        assert caught.value.reason == "forged"

        elsewhere = CodeIssuer("locker-2", keys.codes, clock, render=False)
        _, foreign = elsewhere.issue(instruction_id="i", person="lee", purpose="collect", item="x")
        assert (await locker.simulate_scan(foreign)).reason == "other_lock"
        assert (await locker.simulate_scan("garbage")).reason == "malformed"

        revoked = await locker.issue_code(
            instruction_id="i", person="lee", purpose="collect", item="x"
        )
        await locker.revoke(revoked.code_id)
        assert (await locker.simulate_scan(revoked.payload)).reason == "revoked"
        assert (await locker.status()).door == "closed"


async def test_a_wrong_shared_key_is_refused(
    server: LockServer, keys: LockKeys, clock: SimClock
) -> None:
    intruder_keys = LockKeys(link_key=new_key(), codes=keys.codes)
    locker = tcp_locker(server, intruder_keys, clock)
    with pytest.raises(LockAuthError, match="refused"):
        await locker.start()
    assert server.refused_handshakes == 1
    # The lock is untouched and still serves the rightful assistant.
    async with tcp_locker(server, keys, clock) as rightful:
        assert (await rightful.status()).door == "closed"


async def test_a_fake_lock_cannot_pass_for_the_real_one(keys: LockKeys, clock: SimClock) -> None:
    # A lock emulator that does not hold our link key (say, an impostor on the network).
    impostor = LockServer(LockController(LOCK_ID, keys.codes, clock), new_key(), timeouts=FAST)
    await impostor.start()
    try:
        with pytest.raises(LockAuthError):
            await tcp_locker(impostor, keys, clock).start()
    finally:
        await impostor.stop()


async def test_a_server_that_fakes_auth_ok_is_caught(keys: LockKeys) -> None:
    handled = asyncio.Event()

    async def fake_lock(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        try:
            hello = {
                "type": "hello",
                "version": 1,
                "lock_id": LOCK_ID,
                "epoch": "e",
                "nonce": b64encode(b"\x00" * 16),
            }
            writer.write(encode_frame(encode_message(hello)))
            await reader.read(4096)  # the client's auth, which we cannot check
            ok = {"type": "auth_ok", "mac": b64encode(b"\x01" * 32)}
            writer.write(encode_frame(encode_message(ok)))
            await writer.drain()
            await reader.read(4096)
        finally:
            await close_writer(writer)
            handled.set()

    fake = await asyncio.start_server(fake_lock, "127.0.0.1", 0)
    port = fake.sockets[0].getsockname()[1]
    try:
        reader, writer = await asyncio.open_connection("127.0.0.1", port)
        with pytest.raises(LockAuthError, match="could not prove"):
            await client_handshake(reader, writer, link_key=keys.link_key, handshake_s=1.0)
        await close_writer(writer)
        async with asyncio.timeout(2):
            await handled.wait()
    finally:
        fake.close()
        await fake.wait_closed()


async def test_bad_commands_get_clear_errors_and_keep_the_link(
    server: LockServer, keys: LockKeys, clock: SimClock
) -> None:
    async with tcp_locker(server, keys, clock) as locker:
        with pytest.raises(LockCommandError) as caught:
            await locker.simulate_close()
        assert caught.value.kind == "door_closed"
        with pytest.raises(LockCommandError) as unknown:
            await locker.revoke("no-such-code")
        assert unknown.value.kind == "unknown_code"
        with pytest.raises(LockProtocolError, match="unknown op"):
            await locker.client.request("self_destruct")
        with pytest.raises(LockProtocolError, match="payload"):
            await locker.client.request("scan", payload=42)
        with pytest.raises(LockCommandError) as no_file:
            await locker.reload_keys()
        assert no_file.value.kind == "no_key_source"
        opened = await locker.open_for_maintenance("cleaning")
        assert (opened.person, opened.reason) == ("maintenance", "cleaning")
        assert locker.client.connections == 1


async def test_keys_rotate_without_downtime(tmp_path: Path, clock: SimClock) -> None:
    key_file = tmp_path / "keys.json"
    lock_keys = LockKeys.generate("k1")
    key_file.write_text(lock_keys.to_json())
    controller = LockController(LOCK_ID, LockKeys.from_file(key_file).codes, clock)
    server = LockServer(
        controller,
        lock_keys.link_key,
        timeouts=FAST,
        reload_keys=lambda: LockKeys.from_file(key_file).codes,
    )
    await server.start()
    try:
        assistant_keys = LockKeys.from_file(key_file)
        async with tcp_locker(server, assistant_keys, clock) as locker:
            before = await locker.issue_code(
                instruction_id="i", person="lee", purpose="collect", item="x"
            )
            # 1. a new key goes into the file and the lock reloads it: it accepts both keys.
            rotated = LockKeys.from_file(key_file)
            rotated.codes.rotate("k2", new_key())
            key_file.write_text(rotated.to_json())
            assert await locker.reload_keys() == {"current": "k2", "key_ids": ["k1", "k2"]}
            # 2. the assistant switches to sealing with the new key.
            assistant_keys.codes.replace_with(LockKeys.from_file(key_file).codes)
            after = await locker.issue_code(
                instruction_id="i", person="zhang", purpose="collect", item="y"
            )
            # 3. codes of both keys open the door; nothing was restarted.
            assert (await locker.simulate_scan(before.payload)).kind == "code_accepted"
            await locker.simulate_close()
            assert (await locker.simulate_scan(after.payload)).kind == "code_accepted"
            await locker.simulate_close()
            assert locker.client.connections == 1
    finally:
        await server.stop()
