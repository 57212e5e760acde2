"""The lockers start and stop cleanly, twice in a row, and again after a stop."""

from __future__ import annotations

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.core.clock import SimClock
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.lock.server import LockServer

from .conftest import tcp_locker


async def test_tcp_locker_starts_and_stops_twice(
    server: LockServer, keys: LockKeys, clock: SimClock
) -> None:
    locker = tcp_locker(server, keys, clock)
    for _ in range(2):
        await locker.start()
        await locker.start()
        supervisors = locker.client.tasks
        assert len(supervisors) == 1
        assert (await locker.status()).door == "closed"
        await locker.stop()
        await locker.stop()
        assert all(task.done() for task in supervisors) and not locker.client.tasks
        assert not locker.client.connected
    assert locker.client.connections == 2


async def test_local_locker_listens_once_and_stops_twice(
    controller: LockController, clock: SimClock
) -> None:
    locker = LocalLocker(controller, clock=clock, render_png=False)
    queue = locker.subscribe()
    async with locker:
        await locker.start()  # not a second listener: each event arrives once
        await locker.open_for_maintenance("check")
        assert queue.qsize() == 1
    await locker.stop()
    await locker.simulate_close()  # heard by nobody
    assert queue.qsize() == 1
