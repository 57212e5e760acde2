"""The loop-lag monitor: the longest stall of the event loop within the last minute."""

from __future__ import annotations

import asyncio
import time
from pathlib import Path

from assistantx.service.loop_lag import SCHEDSTAT, CpuWait, LoopLagMonitor


async def test_a_blocking_callback_shows_as_lag() -> None:
    monitor = LoopLagMonitor(interval_s=0.01)
    monitor.start()
    await asyncio.sleep(0.05)
    time.sleep(0.3)  # noqa: ASYNC251 - the point: a callback that holds the loop
    await asyncio.sleep(0.05)
    await monitor.stop()
    assert monitor.max_lag_s() >= 0.25
    # Sleeping is not waiting for a CPU: all of that stall is the service's own doing.
    assert monitor.max_own_lag_s() >= 0.25
    assert monitor.max_own_lag_s() <= monitor.max_lag_s()


def test_the_window_forgets_old_stalls() -> None:
    monitor = LoopLagMonitor(window_s=60)
    monitor.observe(0.9, now=1000.0)
    monitor.observe(0.01, now=1030.0)
    assert monitor.max_lag_s(now=1030.0) == 0.9
    monitor.observe(0.02, now=1061.0)
    assert monitor.max_lag_s(now=1061.0) == 0.02
    assert monitor.worst_ever_s == 0.9


def test_waiting_for_a_cpu_is_not_the_services_own_lag() -> None:
    monitor = LoopLagMonitor(window_s=60)
    monitor.observe(0.4, now=1000.0, cpu_wait_s=0.35)  # starved by other processes
    monitor.observe(0.1, now=1000.5, cpu_wait_s=0.0)  # a callback that held the loop
    assert monitor.max_lag_s(now=1000.5) == 0.4
    assert monitor.max_own_lag_s(now=1000.5) == 0.1
    monitor.observe(0.2, now=1001.0)  # the wait unknown: all of it counts
    assert monitor.max_own_lag_s(now=1001.0) == 0.2


def test_the_cpu_wait_reader_counts_up_or_says_it_cannot() -> None:
    reader = CpuWait()
    try:
        first = reader()
        sum(range(200_000))  # some work: the count may grow, never shrink
        second = reader()
    finally:
        reader.close()
    if Path(SCHEDSTAT).exists():
        assert first is not None and second is not None and 0.0 <= first <= second
    else:
        assert first is None and second is None
