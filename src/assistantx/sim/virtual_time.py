"""Simulated time for many coroutines at once: an event loop whose clock jumps when idle.

``SimClock`` advances time inside each ``sleep`` call, so two robots driving at once add
their driving times up. A fleet needs time in which they overlap: here the loop itself keeps
virtual time. When no callback is ready and the loop would block in its selector until the
next timer, it does not block: virtual time jumps to that timer. Simulated hours then take
the CPU time of the work done in them, and every ``asyncio.sleep``, ``wait_for`` and
``call_later`` runs on simulated time unchanged. Only for in-process simulations: a loop
that never blocks cannot wait for a socket or a thread (``asyncio.to_thread`` would spin).

``LoopClock`` is the ``Clock`` on such a loop (or on any loop: then it is real time).
"""

from __future__ import annotations

import asyncio
import selectors
from collections.abc import Callable, Coroutine
from typing import Any, TypeVar

from assistantx.core.clock import Clock

T = TypeVar("T")


class _JumpingSelector(selectors.DefaultSelector):
    """A selector that, instead of blocking for ``timeout`` seconds, moves the loop's
    virtual clock on by that much."""

    def __init__(self) -> None:
        super().__init__()
        self.loop: VirtualTimeLoop | None = None

    def select(self, timeout: float | None = None) -> list[Any]:
        ready: list[Any] = super().select(0)
        if ready or timeout is None or timeout <= 0 or self.loop is None:
            return ready
        self.loop.virtual_s += timeout
        return []


class VirtualTimeLoop(asyncio.SelectorEventLoop):
    def __init__(self, start_s: float = 0.0) -> None:
        selector = _JumpingSelector()
        super().__init__(selector)
        selector.loop = self
        self.virtual_s = start_s

    def time(self) -> float:
        return self.virtual_s


def run_virtual(main: Callable[[], Coroutine[Any, Any, T]], start_s: float = 0.0) -> T:
    """Run ``main()`` to its end on a fresh virtual-time loop."""
    loop = VirtualTimeLoop(start_s)
    try:
        return loop.run_until_complete(main())
    finally:
        loop.run_until_complete(loop.shutdown_asyncgens())
        loop.close()


class LoopClock(Clock):
    """The running loop's own time: simulated on a ``VirtualTimeLoop``."""

    def now(self) -> float:
        return asyncio.get_running_loop().time()

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(max(0.0, seconds))

    def call_later(self, delay: float, callback: Callable[[], None]) -> None:
        asyncio.get_running_loop().call_later(max(0.0, delay), callback)

    async def wait_event(self, event: asyncio.Event, timeout: float) -> bool:  # noqa: ASYNC109
        try:
            await asyncio.wait_for(event.wait(), max(0.0, timeout))
        except TimeoutError:
            return event.is_set()
        return True
