"""The loop-lag monitor: the longest stall of the event loop within the last minute."""

from __future__ import annotations

import asyncio
import time

from assistantx.service.loop_lag import LoopLagMonitor


async def test_a_blocking_callback_shows_as_lag() -> None:
    monitor = LoopLagMonitor(interval_s=0.01)
    monitor.start()
    await asyncio.sleep(0.05)
    time.sleep(0.3)  # noqa: ASYNC251 - the point: a callback that holds the loop
    await asyncio.sleep(0.05)
    await monitor.stop()
    assert monitor.max_lag_s() >= 0.25


def test_the_window_forgets_old_stalls() -> None:
    monitor = LoopLagMonitor(window_s=60)
    monitor.observe(0.9, now=1000.0)
    monitor.observe(0.01, now=1030.0)
    assert monitor.max_lag_s(now=1030.0) == 0.9
    monitor.observe(0.02, now=1061.0)
    assert monitor.max_lag_s(now=1061.0) == 0.02
    assert monitor.worst_ever_s == 0.9
