"""Event streams across network faults: nothing missed, nothing counted twice."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.protocol.link import LinkTimeouts
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.core.clock import SimClock
from assistantx.core.ports.lock import LockEvent
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from helpers.eventually import assert_quiet, eventually

from .conftest import FAST, LOCK_ID, QUICK_RETRY
from .proxy import FaultyProxy


@pytest.fixture
async def proxy(server: LockServer) -> AsyncIterator[FaultyProxy]:
    faulty = FaultyProxy(server.address[1])
    await faulty.start()
    yield faulty
    await faulty.stop()


def _locker_via(proxy: FaultyProxy, keys: LockKeys, clock: SimClock, **kw: object) -> TcpLocker:
    assert proxy._server is not None
    port = proxy._server.sockets[0].getsockname()[1]
    timeouts = kw.pop("timeouts", FAST)
    assert isinstance(timeouts, LinkTimeouts)
    return TcpLocker(
        "127.0.0.1",
        port,
        keys,
        clock=clock,
        timeouts=timeouts,
        backoff=QUICK_RETRY,
        render_png=False,
    )


async def _hand_over(locker: TcpLocker, person: str) -> None:
    qr = await locker.issue_code(instruction_id="ins", person=person, purpose="seal", item="doc")
    assert (await locker.simulate_scan(qr.payload)).kind == "code_accepted"
    await locker.simulate_close()


async def _drain(queue: asyncio.Queue[LockEvent], count: int) -> list[LockEvent]:
    async with asyncio.timeout(3):
        events = [await queue.get() for _ in range(count)]
    await assert_quiet(queue, 0.1, what="event delivered twice")
    return events


async def test_a_client_reconnecting_mid_stream_misses_nothing_and_counts_nothing_twice(
    server: LockServer, proxy: FaultyProxy, keys: LockKeys, clock: SimClock
) -> None:
    async with _locker_via(proxy, keys, clock) as locker:
        events = locker.subscribe()
        await _hand_over(locker, "lee")  # events 1-3

        proxy.refusing = True
        proxy.cut()
        await eventually(lambda: not locker.client.connected, what="the link to drop", timeout_s=3)
        # Physical acts at the locker while the assistant is cut off: events 4-5.
        server.controller.open_for_maintenance("jammed door")
        server.controller.close()
        proxy.refusing = False
        await eventually(lambda: locker.client.connected, what="the link to come back", timeout_s=3)

        await _hand_over(locker, "zhang")  # events 6-8
        received = await _drain(events, 8)

    assert [e.seq for e in received] == list(range(1, 9))
    assert [(e.kind, e.person) for e in received][3:5] == [
        ("door_opened", "maintenance"),
        ("door_closed", "maintenance"),
    ]
    assert locker.client.connections == 2
    assert locker.client.gaps == 0


async def test_a_half_open_link_is_detected_and_replaced(
    server: LockServer, proxy: FaultyProxy, keys: LockKeys, clock: SimClock
) -> None:
    eager = LinkTimeouts(
        connect_s=2.0, handshake_s=0.5, frame_s=0.5, idle_s=1.0, keepalive_s=0.1, request_s=0.3
    )
    async with _locker_via(proxy, keys, clock, timeouts=eager) as locker:
        events = locker.subscribe()
        proxy.swallow()  # the link looks up, but nothing gets through any more
        server.controller.open_for_maintenance()  # event 1, swallowed on the old link
        await eventually(
            lambda: locker.client.connections == 2, what="a second connection", timeout_s=3
        )
        server.controller.close()  # event 2, on the new link
        received = await _drain(events, 2)
        assert [(e.seq, e.kind) for e in received] == [(1, "door_opened"), (2, "door_closed")]
        # The lock drops the dead session by itself once it has been idle too long.
        await eventually(
            lambda: server.connection_count == 1, what="one connection at the lock", timeout_s=3
        )


async def test_a_restarted_lock_starts_a_new_count(keys: LockKeys, clock: SimClock) -> None:
    first = LockServer(LockController(LOCK_ID, keys.codes, clock), keys.link_key, timeouts=FAST)
    host, port = await first.start()
    locker = TcpLocker(
        host, port, keys, clock=clock, timeouts=FAST, backoff=QUICK_RETRY, render_png=False
    )
    async with locker:
        events = locker.subscribe()
        await _hand_over(locker, "lee")
        old_epoch = locker.client.epoch
        await first.stop()
        second = LockServer(
            LockController(LOCK_ID, keys.codes, clock), keys.link_key, port=port, timeouts=FAST
        )
        await second.start()
        try:
            await eventually(
                lambda: locker.client.connected and locker.client.epoch != old_epoch,
                what="a connection to the restarted lock",
                timeout_s=3,
            )
            await _hand_over(locker, "zhang")
            received = await _drain(events, 6)
        finally:
            await second.stop()
    assert [(e.seq, e.person) for e in received] == [
        (1, "lee"),
        (2, "lee"),
        (3, "lee"),
        (1, "zhang"),
        (2, "zhang"),
        (3, "zhang"),
    ]
