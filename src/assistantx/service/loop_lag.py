"""How long the event loop was kept from running: the longest stall in the last minute.

A ticker sleeps ``interval_s`` again and again and measures how late it wakes up; a callback
that holds the loop for 300 ms makes the next wake-up about 300 ms late, so the longest
lateness seen is (to within one interval) the longest callback that ran. Kept per second for
the last ``window_s`` seconds, so ``/metrics`` shows the worst stall of the last minute, not of
all time. Unlike ``PYTHONASYNCIODEBUG`` it costs nothing measurable and cannot be switched off
by the server.

A late wake-up is not always the service's doing: on a machine with more runnable threads than
cores the loop's thread waits for a core (a burst of 200 POSTs on the shared 2-core machine:
1.4 s on a CPU, 6.0 s waiting for one, in 8.5 s). Where Linux says how long the thread waited
for a CPU (``/proc/thread-self/schedstat``), that wait is also taken off each lateness: the
longest of those, ``max_own_lag_s``, is what the service's own code held the loop (callbacks
running or blocking); elsewhere it equals the lag.
"""

from __future__ import annotations

import asyncio
import logging
import os
import time
from collections import deque

from assistantx.core.lifecycle import cancel_and_wait

logger = logging.getLogger(__name__)

WARN_S = 0.5  # a stall this long is logged


SCHEDSTAT = "/proc/thread-self/schedstat"  # ns on a CPU, ns waiting for one, time slices


class CpuWait:
    """Seconds the calling thread has waited for a CPU so far (Linux), or None where the
    system does not say. The file is kept open and re-read from its start."""

    def __init__(self) -> None:
        try:
            self._fd: int | None = os.open(SCHEDSTAT, os.O_RDONLY)
        except OSError:
            self._fd = None

    def __call__(self) -> float | None:
        if self._fd is None:
            return None
        try:
            return int(os.pread(self._fd, 128, 0).split()[1]) / 1e9
        except (OSError, IndexError, ValueError):
            return None

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None


class LoopLagMonitor:
    def __init__(self, interval_s: float = 0.02, window_s: int = 60) -> None:
        self.interval_s = interval_s
        self.window_s = window_s
        self._seconds: deque[tuple[int, float]] = deque()  # (whole second, worst lag in it)
        self._own: deque[tuple[int, float]] = deque()  # the same, less the waits for a CPU
        self._task: asyncio.Task[None] | None = None
        self.worst_ever_s = 0.0

    def start(self) -> None:
        if self._task is None:
            self._task = asyncio.create_task(self._tick(), name="loop-lag-monitor")

    async def stop(self) -> None:
        await cancel_and_wait(self._task)
        self._task = None

    def observe(
        self, lag_s: float, now: float | None = None, *, cpu_wait_s: float | None = None
    ) -> None:
        """A wake-up ``lag_s`` late; ``cpu_wait_s``: how much of it the loop's thread waited
        for a CPU (None: unknown, all of it counts as the service's own)."""
        second = int(time.monotonic() if now is None else now)
        own_s = lag_s if cpu_wait_s is None else max(0.0, lag_s - cpu_wait_s)
        for seconds, value in ((self._seconds, lag_s), (self._own, own_s)):
            self._keep(seconds, second, value)
        self.worst_ever_s = max(self.worst_ever_s, lag_s)
        if own_s >= WARN_S:
            logger.warning("the event loop was blocked for %.0f ms", 1000 * own_s)

    def _keep(self, seconds: deque[tuple[int, float]], second: int, value: float) -> None:
        if seconds and seconds[-1][0] == second:
            if value > seconds[-1][1]:
                seconds[-1] = (second, value)
        else:
            seconds.append((second, value))
        while seconds and seconds[0][0] <= second - self.window_s:
            seconds.popleft()

    def max_lag_s(self, now: float | None = None) -> float:
        """The longest stall within the window (seconds)."""
        return self._max(self._seconds, now)

    def max_own_lag_s(self, now: float | None = None) -> float:
        """The longest stall within the window less the loop thread's waits for a CPU."""
        return self._max(self._own, now)

    def _max(self, seconds: deque[tuple[int, float]], now: float | None) -> float:
        second = int(time.monotonic() if now is None else now)
        return max((lag for s, lag in seconds if s > second - self.window_s), default=0.0)

    async def _tick(self) -> None:
        cpu_wait = CpuWait()  # opened here: the file is the loop thread's own
        try:
            while True:
                before, waited_before = time.monotonic(), cpu_wait()
                await asyncio.sleep(self.interval_s)
                after, waited_after = time.monotonic(), cpu_wait()
                waited = (
                    None
                    if waited_before is None or waited_after is None
                    else waited_after - waited_before
                )
                self.observe(max(0.0, after - before - self.interval_s), after, cpu_wait_s=waited)
        finally:
            cpu_wait.close()
