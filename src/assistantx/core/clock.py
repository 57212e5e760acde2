"""Clocks: wall time for the service, simulated time for the simulator and the evaluation.

Everything that waits, schedules or timestamps takes a Clock, so a simulated hour of driving
and waiting costs no real time. ``SimClock`` is a discrete-event clock: callbacks scheduled
with ``call_later`` run in time order as the clock advances, and ``wait_event`` jumps straight
to the next scheduled callback instead of sleeping. With several coroutines sleeping at once
the advances add up (over-estimating elapsed time); the simulator runs one instruction per
office in the evaluation, so this matters only for the concurrency tests, where the service
uses wall time anyway.
"""

from __future__ import annotations

import asyncio
import heapq
import itertools
import time
from abc import ABC, abstractmethod
from collections.abc import Callable

_YIELDS = 4  # let consumers (inbox dispatcher, waiters) run after simulated events fire


class Clock(ABC):
    @abstractmethod
    def now(self) -> float:
        """Seconds since the epoch (wall) or since the simulation started (sim)."""

    def timer(self) -> float:
        """Seconds as ``sleep`` and ``wait_event`` count them, for the deadline of a wait;
        the same as ``now()`` except on a sped-up WallClock (never a time of day)."""
        return self.now()

    @abstractmethod
    async def sleep(self, seconds: float) -> None:
        """Let ``seconds`` pass."""

    @abstractmethod
    def call_later(self, delay: float, callback: Callable[[], None]) -> None:
        """Run ``callback`` once ``delay`` seconds have passed."""

    @abstractmethod
    async def wait_event(self, event: asyncio.Event, timeout: float) -> bool:  # noqa: ASYNC109
        """Wait until ``event`` is set (True) or ``timeout`` seconds pass (False)."""


class WallClock(Clock):
    """Real time; ``speedup`` shortens the simulated durations only (a demo where the robot
    drives and simulated colleagues answer 10x faster).

    ``now()`` is always the real time of day: it stamps instructions, messages and reports,
    which people compare with their own clocks. Waits (``sleep``, ``call_later``,
    ``wait_event``) take ``1/speedup`` of their duration, and ``timer()`` runs ``speedup``
    times faster than real time, so a wait's deadline ``timer() + 300`` passes when its
    ``wait_event(.., 300)`` would.
    """

    def __init__(self, speedup: float = 1.0) -> None:
        if speedup <= 0:
            raise ValueError("speedup must be positive")
        self.speedup = speedup
        self._origin = time.monotonic()

    def now(self) -> float:
        return time.time()

    def timer(self) -> float:
        return (time.monotonic() - self._origin) * self.speedup

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(max(0.0, seconds) / self.speedup)

    def call_later(self, delay: float, callback: Callable[[], None]) -> None:
        asyncio.get_running_loop().call_later(max(0.0, delay) / self.speedup, callback)

    async def wait_event(self, event: asyncio.Event, timeout: float) -> bool:  # noqa: ASYNC109
        try:
            await asyncio.wait_for(event.wait(), max(0.0, timeout) / self.speedup)
        except TimeoutError:
            return event.is_set()
        return True


class SimClock(Clock):
    def __init__(self, start: float = 0.0) -> None:
        self._now = start
        self._queue: list[tuple[float, int, Callable[[], None]]] = []
        self._seq = itertools.count()

    def now(self) -> float:
        return self._now

    def call_later(self, delay: float, callback: Callable[[], None]) -> None:
        heapq.heappush(self._queue, (self._now + max(0.0, delay), next(self._seq), callback))

    def next_event_time(self) -> float | None:
        return self._queue[0][0] if self._queue else None

    def advance(self, seconds: float) -> None:
        """Move time forward, running every callback that falls due on the way, in order."""
        if seconds < 0:
            raise ValueError("time does not run backwards")
        target = self._now + seconds
        while self._queue and self._queue[0][0] <= target:
            due, _, callback = heapq.heappop(self._queue)
            self._now = max(self._now, due)
            callback()
        self._now = target

    async def sleep(self, seconds: float) -> None:
        self.advance(max(0.0, seconds))
        for _ in range(_YIELDS):
            await asyncio.sleep(0)

    async def wait_event(self, event: asyncio.Event, timeout: float) -> bool:  # noqa: ASYNC109
        deadline = self._now + max(0.0, timeout)
        for _ in range(_YIELDS):
            await asyncio.sleep(0)
        while not event.is_set():
            nxt = self.next_event_time()
            if self._now >= deadline:
                return False
            step = deadline - self._now if nxt is None else min(nxt, deadline) - self._now
            self.advance(max(0.0, step))
            for _ in range(_YIELDS):
                await asyncio.sleep(0)
        return True
