"""The physical side of the office for the Matrix tests: the simulated robot base and an
in-process locker on a sped-up wall clock, and a person walking up to the robot to scan.

Only the physical world is simulated here; messages go through the real homeserver.
"""

from __future__ import annotations

import asyncio
import hashlib

from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.core.clock import Clock
from assistantx.core.ports.lock import LockEvent
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.office import SimRobot
from synapse.helpers import WAIT_S


class ObservedLocker(LocalLocker):
    """The in-process locker, also telling the test when the robot is waiting at it."""

    def __init__(self, clock: Clock) -> None:
        key = hashlib.sha256(b"assistantx-matrix-test").digest()
        controller = LockController("locker-matrix", Keyring.single("test", key), clock)
        super().__init__(controller, clock=clock, render_png=True)
        self.waiting = asyncio.Event()

    def subscribe(self, notify: asyncio.Event | None = None) -> asyncio.Queue[LockEvent]:
        queue = super().subscribe(notify)
        self.waiting.set()
        return queue

    def unsubscribe(self, queue: asyncio.Queue[LockEvent]) -> None:
        super().unsubscribe(queue)
        if not self._subscribers:
            self.waiting.clear()


async def hand_over_at_robot(
    robot: SimRobot, locker: ObservedLocker, place: str, payload: str
) -> list[LockEvent]:
    """A person at ``place`` waits for the robot to wait there at its locker, scans
    ``payload``, does what the code is for and shuts the door; returns the lock's events."""
    await asyncio.wait_for(locker.waiting.wait(), WAIT_S)
    assert (robot.place, robot.moving) == (place, False), "the robot waits somewhere else"
    decision = await locker.simulate_scan(payload)
    if decision.kind != "code_accepted":
        return [decision]
    return [decision, await locker.simulate_close()]
