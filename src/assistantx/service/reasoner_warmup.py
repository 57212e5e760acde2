"""The reasoner's factory, built after the service is ready instead of before.

The symbolic reasoner's factory reads the office into its lexicon (every word's inflections
from lemminflect's tables): about a third of a CPU-second, a fifth of a start, and nothing
before ``/readyz`` needs it. The factory is built in a worker thread once the service is
ready; the first instruction that asks for a reasoner before it is done waits for it (or
builds it itself when the warm-up was never started). A stop does not wait for the warm-up
(its thread is a daemon: a start stopped at once stopped in 4 s instead of 1.5 while the
lexicon was still being read).
"""

from __future__ import annotations

import asyncio
import logging
import threading
from collections.abc import Callable

from assistantx.agents.base import Reasoner, ReasonerFactory

logger = logging.getLogger(__name__)

# The reasoners whose factory has nothing to check at start (no model, no plug-in to load),
# so building it later cannot turn a start-up error into a first-instruction one.
DEFERRED_REASONERS = frozenset({"symbolic"})


class DeferredFactory:
    """A reasoner factory whose own factory is built once, on first need or by ``warm``."""

    def __init__(self, build: Callable[[], ReasonerFactory]) -> None:
        self._build = build
        self._factory: ReasonerFactory | None = None
        self._lock = threading.Lock()

    def __call__(self) -> Reasoner:
        return self.factory()()

    def factory(self) -> ReasonerFactory:
        """The built factory (built now, or waited for, when it is not yet)."""
        factory = self._factory
        if factory is None:
            with self._lock:  # a warm-up under way: wait for it rather than build twice
                if self._factory is None:
                    self._factory = self._build()
                factory = self._factory
        return factory

    async def built(self) -> None:
        """Wait for the factory without holding the event loop: a call to the factory before
        the warm-up ends waits on its lock, and from a coroutine that held the loop for the
        rest of the warm-up (0.2-0.5 s for the first instruction after ready in
        bench/service_load.py). A failure is left for the call that needs the factory."""
        if self._factory is None:
            try:
                await asyncio.to_thread(self.factory)
            except Exception:  # raised again to the caller of the factory
                logger.debug("the reasoner's factory failed to build", exc_info=True)

    def warm_in_background(self) -> threading.Thread:
        """Build the factory in a daemon thread (the loop keeps serving meanwhile). Daemon:
        a stop right after the start does not wait for it (it only builds tables); a
        failure is logged here and raised again on first use."""
        thread = threading.Thread(target=self._warm, name="reasoner-warm-up", daemon=True)
        thread.start()
        return thread

    def _warm(self) -> None:
        try:
            self.factory()
        except Exception as exc:  # raised again to the first instruction that needs it
            logger.warning("building the reasoner failed: %s", exc)
