"""Admission apart from execution: a POST journals the instruction and queues it; one starter
task starts queued instructions in the order they were admitted.

Starting an instruction builds its reasoner, runs the start hooks and checkpoints its memory;
none of that happens inside the request, so an acknowledgement never waits behind another
instruction's work. An instruction cancelled while it waits here is never started and ends
``cancelled``. On shutdown the starter stops; what it had not started stays ``queued`` in the
journal and is started on the next start-up (``ServiceRuntime._resume``).
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Awaitable, Callable

from assistantx.core.office import PersonId
from assistantx.runtime.assistant import Assistant
from assistantx.store.journal import InstructionRecord, Journal

logger = logging.getLogger(__name__)


class Admission:
    def __init__(
        self,
        assistant: Assistant,
        journal: Journal,
        reasoner_built: Callable[[], Awaitable[None]] | None = None,
    ) -> None:
        """``reasoner_built``: awaited before each start, so that starting an instruction
        never waits on the loop for a reasoner still being built (service.reasoner_warmup)."""
        self._assistant = assistant
        self._reasoner_built = reasoner_built
        self._journal = journal
        self._queue: asyncio.Queue[InstructionRecord | None] = asyncio.Queue()
        self._waiting: set[str] = set()
        self._task: asyncio.Task[None] | None = None
        self._stopping = False

    @property
    def waiting(self) -> int:
        return len(self._waiting)

    def start(self) -> None:
        if self._task is None:
            self._task = asyncio.create_task(self._start_admitted(), name="admission-starter")

    async def stop(self) -> None:
        if self._task is None:
            return
        self._stopping = True  # finishes the start under way, starts nothing more
        self._queue.put_nowait(None)
        with contextlib.suppress(asyncio.CancelledError):
            await self._task
        self._task = None

    def admit(self, record: InstructionRecord) -> None:
        self._waiting.add(record.id)
        self._queue.put_nowait(record)

    async def withdraw(self, instruction_id: str) -> bool:
        """Cancel an instruction that was admitted and not started yet."""
        if instruction_id not in self._waiting:
            return False
        self._waiting.discard(instruction_id)
        await self._journal.aset_status(instruction_id, "cancelled")
        return True

    async def _start_admitted(self) -> None:
        while True:
            record = await self._queue.get()
            if record is None or self._stopping:
                return
            if self._reasoner_built is not None:
                await self._reasoner_built()  # still withdrawable meanwhile
                if self._stopping:
                    return
            if record.id not in self._waiting:
                continue  # withdrawn
            self._waiting.discard(record.id)  # from here on, cancelling it cancels the run
            try:
                await self._assistant.submit(  # journaled as resolved by the route
                    PersonId(record.requester), record.text, instruction_id=record.id
                )
            except Exception:
                logger.exception("could not start instruction %s", record.id)
                await self._journal.aset_status(record.id, "failed")
