"""How long the event loop was kept from running: the longest stall in the last minute.

A ticker sleeps ``interval_s`` again and again and measures how late it wakes up; a callback
that holds the loop for 300 ms makes the next wake-up about 300 ms late, so the longest
lateness seen is (to within one interval) the longest callback that ran. Kept per second for
the last ``window_s`` seconds, so ``/metrics`` shows the worst stall of the last minute, not of
all time. Unlike ``PYTHONASYNCIODEBUG`` it costs nothing measurable and cannot be switched off
by the server.
"""

from __future__ import annotations

import asyncio
import logging
import time
from collections import deque

from assistantx.core.lifecycle import cancel_and_wait

logger = logging.getLogger(__name__)

WARN_S = 0.5  # a stall this long is logged


class LoopLagMonitor:
    def __init__(self, interval_s: float = 0.02, window_s: int = 60) -> None:
        self.interval_s = interval_s
        self.window_s = window_s
        self._seconds: deque[tuple[int, float]] = deque()  # (whole second, worst lag in it)
        self._task: asyncio.Task[None] | None = None
        self.worst_ever_s = 0.0

    def start(self) -> None:
        if self._task is None:
            self._task = asyncio.create_task(self._tick(), name="loop-lag-monitor")

    async def stop(self) -> None:
        await cancel_and_wait(self._task)
        self._task = None

    def observe(self, lag_s: float, now: float | None = None) -> None:
        second = int(time.monotonic() if now is None else now)
        if self._seconds and self._seconds[-1][0] == second:
            if lag_s > self._seconds[-1][1]:
                self._seconds[-1] = (second, lag_s)
        else:
            self._seconds.append((second, lag_s))
        while self._seconds and self._seconds[0][0] <= second - self.window_s:
            self._seconds.popleft()
        self.worst_ever_s = max(self.worst_ever_s, lag_s)
        if lag_s >= WARN_S:
            logger.warning("the event loop was blocked for %.0f ms", 1000 * lag_s)

    def max_lag_s(self, now: float | None = None) -> float:
        """The longest stall within the window (seconds)."""
        second = int(time.monotonic() if now is None else now)
        return max((lag for s, lag in self._seconds if s > second - self.window_s), default=0.0)

    async def _tick(self) -> None:
        while True:
            before = time.monotonic()
            await asyncio.sleep(self.interval_s)
            after = time.monotonic()
            self.observe(max(0.0, after - before - self.interval_s), after)
