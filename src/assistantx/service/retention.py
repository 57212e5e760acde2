"""The journal's retention policy: finished instructions' traces compacted after N days.

Once a day (and at start-up) the traces — trace events and the short-term memory checkpoint —
of instructions that ended more than ``ASSISTANTX_JOURNAL_RETENTION_DAYS`` ago are dropped;
their outcome, summary and step count stay, as do every message (the audit of who was told
what) and every memory update. 0 keeps everything.
"""

from __future__ import annotations

import asyncio
import logging
import time

from assistantx.core.lifecycle import cancel_and_wait
from assistantx.store.journal import Journal

logger = logging.getLogger(__name__)

EVERY_S = 24 * 3600.0


class Retention:
    def __init__(self, journal: Journal, days: float) -> None:
        self._journal = journal
        self.days = days
        self._task: asyncio.Task[None] | None = None

    def start(self) -> None:
        if self.days > 0 and self._task is None:
            self._task = asyncio.create_task(self._run(), name="journal-retention")

    async def stop(self) -> None:
        await cancel_and_wait(self._task)
        self._task = None

    async def apply(self) -> int:
        cut = time.time() - self.days * 86400
        compacted = await self._journal.acompact(cut)
        if compacted:
            logger.info("compacted the traces of %d finished instructions", compacted)
        return compacted

    async def _run(self) -> None:
        while True:
            try:
                await self.apply()
            except Exception:
                logger.exception("journal retention failed; retrying tomorrow")
            await asyncio.sleep(EVERY_S)
