"""Clocks: wall time for the service, simulated time for the simulator and the evaluation.

Everything that waits or timestamps takes a Clock, so a simulated hour of driving and waiting
costs no real time. ``SimClock`` is a virtual clock: ``sleep(s)`` advances it by ``s`` and
yields once to the event loop. With several coroutines sleeping at once the advances add up,
which over-estimates elapsed time; the simulator runs one instruction per office, so this
never matters there, and the service uses wall time.
"""

from __future__ import annotations

import asyncio
import time
from abc import ABC, abstractmethod


class Clock(ABC):
    @abstractmethod
    def now(self) -> float:
        """Seconds since the epoch (wall) or since the simulation started (sim)."""

    @abstractmethod
    async def sleep(self, seconds: float) -> None:
        """Let ``seconds`` pass."""


class WallClock(Clock):
    def __init__(self, speedup: float = 1.0) -> None:
        if speedup <= 0:
            raise ValueError("speedup must be positive")
        self.speedup = speedup

    def now(self) -> float:
        return time.time()

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(max(0.0, seconds) / self.speedup)


class SimClock(Clock):
    def __init__(self, start: float = 0.0) -> None:
        self._now = start

    def now(self) -> float:
        return self._now

    def advance(self, seconds: float) -> None:
        if seconds < 0:
            raise ValueError("time does not run backwards")
        self._now += seconds

    async def sleep(self, seconds: float) -> None:
        self.advance(max(0.0, seconds))
        await asyncio.sleep(0)
