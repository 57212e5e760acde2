"""Fixtures of the lock protocol's tests: a lock server on 127.0.0.1 and a TCP locker for it;
the keys, clock and controller come from ``helpers.lock`` (shared with ``tests/sim/lock``)."""

from __future__ import annotations

from collections.abc import AsyncIterator
from typing import Any

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.adapters.lock.protocol.link import LinkTimeouts
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.core.backoff import Backoff
from assistantx.core.clock import SimClock
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer
from helpers.lock import (  # noqa: F401 (fixtures)
    LOCK_ID,
    clock_fixture,
    controller_fixture,
    issuer_fixture,
    keys_fixture,
)

# Short enough that timeout paths run in well under a second, long enough for a busy CI box.
FAST = LinkTimeouts(
    connect_s=3.0, handshake_s=0.5, frame_s=0.5, idle_s=1.5, keepalive_s=0.2, request_s=2.0
)
QUICK_RETRY = Backoff(initial_s=0.02, max_s=0.2)


@pytest.fixture
async def server(keys: LockKeys, clock: SimClock) -> AsyncIterator[LockServer]:
    controller = LockController(LOCK_ID, keys.codes, clock)
    lock_server = LockServer(controller, keys.link_key, timeouts=FAST)
    await lock_server.start()
    yield lock_server
    await lock_server.stop()


def tcp_locker(server: LockServer, keys: LockKeys, clock: SimClock, **kwargs: Any) -> TcpLocker:
    host, port = server.address
    kwargs.setdefault("render_png", False)
    return TcpLocker(
        host, port, keys, clock=clock, timeouts=FAST, backoff=QUICK_RETRY, expiry_s=600, **kwargs
    )
