"""The cyclic garbage collector kept from holding the event loop: survivors are frozen.

A full collection walks every object the collector tracks, and it runs on whichever thread
allocated last, mostly the event loop's. With 200 instructions running (their memories,
traces, tasks: 70,000-125,000 objects besides what start-up froze) one full collection held the
loop 50-240 ms on the loaded 2-core machine, one every 5-10 s (bench/service_load.py: the
longest stalls of the loop were these). What survives a full collection is mostly long-lived
(running instructions, the latest finished ones, the memory graph), so it is frozen as the
collection ends (``gc.freeze``): the next full collection walks only what came since, and
what it takes is proportional to what was allocated and kept since, not to the whole heap.

A frozen object is still freed when its last reference goes (reference counting); what the
collector no longer finds is a reference cycle among frozen objects. So once every
``thorough_every_s`` a full collection first unfreezes everything (``gc.unfreeze``) and walks
the whole heap as before (one long pause), collecting such cycles; its survivors are frozen
again. Installed by ``assistantx serve`` (the CLI owns the process's collector, as it owns the
freeze of start-up); an app embedded elsewhere keeps the interpreter's defaults.

Paced (``pace``): the interpreter starts a full collection when the objects promoted since the
last one exceed a quarter of what that one kept, inside whichever callback allocated last; a
request could wait behind one that walked tens of seconds of survivors (24-35 ms of the loop's
CPU each with 200 instructions running). Paced, the interpreter never starts one itself (the
oldest generation's threshold is out of reach); the event loop runs one every ``PACE_S`` at a
moment when no request is in flight (waiting at most ``PACE_HOLD_MAX_S`` for one), so each
walks about a second of survivors, not half a minute of them, and never inside a request.
"""

from __future__ import annotations

import asyncio
import gc
import logging
import time
from collections.abc import Callable
from typing import Any

logger = logging.getLogger(__name__)

THOROUGH_EVERY_S = 600.0  # a full collection that walks the frozen objects too, this often
OLDEST = 2  # the generation a full collection collects
PACE_S = 1.0  # paced: a full collection this often
PACE_HOLD_MAX_S = 0.25  # ... waiting at most this long for no request to be in flight
PACE_RETRY_S = 0.005  # how soon it looks again while requests are in flight
_NEVER = 2**30  # the oldest generation's threshold while paced: the interpreter never gets there


class SurvivorFreezer:
    """``install()`` it once; ``uninstall()`` takes it out again (tests)."""

    def __init__(
        self,
        thorough_every_s: float = THOROUGH_EVERY_S,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.thorough_every_s = thorough_every_s
        self._clock = clock
        self._last_thorough = clock()
        self.frozen_collections = 0  # full collections whose survivors were frozen
        self.thorough_collections = 0  # of them, those that walked the frozen objects too
        self.paced_collections = 0  # of them, those the event loop ran (``pace``)
        self._threshold: tuple[int, int, int] | None = None  # the interpreter's, while paced
        self._pacer: asyncio.TimerHandle | None = None

    def install(self) -> None:
        if self._on_collection not in gc.callbacks:
            gc.callbacks.append(self._on_collection)

    def uninstall(self) -> None:
        if self._on_collection in gc.callbacks:
            gc.callbacks.remove(self._on_collection)
        if self._pacer is not None:
            self._pacer.cancel()
            self._pacer = None
        if self._threshold is not None:
            gc.set_threshold(*self._threshold)
            self._threshold = None

    def pace(
        self,
        loop: asyncio.AbstractEventLoop,
        requests_in_flight: Callable[[], int],
        *,
        pace_s: float = PACE_S,
        hold_max_s: float = PACE_HOLD_MAX_S,
    ) -> None:
        """From now on full collections run on ``loop`` every ``pace_s``, when
        ``requests_in_flight()`` is 0 (or ``hold_max_s`` after they were due); the
        interpreter's own trigger for them is off until ``uninstall``. Younger generations
        are collected as before."""
        if self._threshold is None:
            self._threshold = gc.get_threshold()
            young, middle, _ = self._threshold
            gc.set_threshold(young, middle, _NEVER)
        if self._pacer is not None:
            self._pacer.cancel()

        def collect(hold_until: float | None = None) -> None:
            now = loop.time()
            hold_until = now + hold_max_s if hold_until is None else hold_until
            if requests_in_flight() and now < hold_until:
                self._pacer = loop.call_later(PACE_RETRY_S, collect, hold_until)
                return
            gc.collect(OLDEST)  # _on_collection freezes its survivors
            self.paced_collections += 1
            self._pacer = loop.call_later(pace_s, collect)

        self._pacer = loop.call_later(pace_s, collect)

    def _on_collection(self, phase: str, info: dict[str, Any]) -> None:
        if info["generation"] != OLDEST:
            return
        if phase == "start":
            now = self._clock()
            if now - self._last_thorough >= self.thorough_every_s:
                # Called before the collection walks its generation: what is unfrozen now
                # is walked by this very collection.
                gc.unfreeze()
                self._last_thorough = now
                self.thorough_collections += 1
        else:
            gc.freeze()  # what survived: out of the next full collections' walk
            self.frozen_collections += 1
