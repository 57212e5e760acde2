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
"""

from __future__ import annotations

import gc
import logging
import time
from collections.abc import Callable
from typing import Any

logger = logging.getLogger(__name__)

THOROUGH_EVERY_S = 600.0  # a full collection that walks the frozen objects too, this often
OLDEST = 2  # the generation a full collection collects


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

    def install(self) -> None:
        if self._on_collection not in gc.callbacks:
            gc.callbacks.append(self._on_collection)

    def uninstall(self) -> None:
        if self._on_collection in gc.callbacks:
            gc.callbacks.remove(self._on_collection)

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
