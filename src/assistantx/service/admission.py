"""Admission apart from execution: a POST journals the instruction and queues it; one starter
task starts queued instructions in the order they were admitted.

Starting an instruction builds its reasoner, runs the start hooks and checkpoints its memory;
none of that happens inside the request, so an acknowledgement never waits behind another
instruction's work. An instruction cancelled while it waits here is never started and ends
``cancelled``. On shutdown the starter stops; what it had not started stays ``queued`` in the
journal and is started on the next start-up (``ServiceRuntime._resume``).

While submissions are arriving the starter holds back (for a pause of ``QUIET_S`` in them, at
most ``HOLD_MAX_S`` per start): a started instruction takes its first steps on the same event
loop, and in a burst of 200 POSTs the later ones waited behind the first ones' instructions
(bench/service_load.py); acknowledging the burst first delays those starts by about as long as
the burst takes, and a steady stream of submissions still starts one every ``HOLD_MAX_S``.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Awaitable, Callable, Iterator

from assistantx.core.office import PersonId
from assistantx.runtime.assistant import Assistant
from assistantx.store.journal import InstructionRecord, Journal

logger = logging.getLogger(__name__)

QUIET_S = 0.05  # the starter waits for a pause this long in the submissions ...
HOLD_MAX_S = 0.5  # ... but holds one start back no longer than this


class Admission:
    def __init__(
        self,
        assistant: Assistant,
        journal: Journal,
        reasoner_built: Callable[[], Awaitable[None]] | None = None,
        *,
        turn: Callable[[], Awaitable[None]] | None = None,
    ) -> None:
        """``reasoner_built``: awaited before each start, so that starting an instruction
        never waits on the loop for a reasoner still being built (service.reasoner_warmup);
        ``turn``: awaited last before each start, as a running instruction awaits its turn
        between two events (``service.turns``): a start waits for the requests in flight."""
        self._assistant = assistant
        self._reasoner_built = reasoner_built
        self._turn = turn
        self._journal = journal
        self._queue: asyncio.Queue[InstructionRecord | None] = asyncio.Queue()
        self._waiting: set[str] = set()
        self._task: asyncio.Task[None] | None = None
        self._stopping = False
        self._arriving = 0  # submissions being journaled now
        self._last_arrival = float("-inf")  # (loop time) when the last one was journaled

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

    @contextlib.contextmanager
    def arriving(self) -> Iterator[None]:
        """Around a submission's journaling: the starter holds back meanwhile."""
        self._arriving += 1
        try:
            yield
        finally:
            self._arriving -= 1
            self._last_arrival = asyncio.get_running_loop().time()

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
            await self._pause_in_submissions()
            if self._turn is not None and not self._stopping:
                await self._turn()
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

    async def _pause_in_submissions(self) -> None:
        """Wait while submissions are arriving, for a pause of ``QUIET_S`` in them (at most
        ``HOLD_MAX_S``); no wait when none arrived lately."""
        loop = asyncio.get_running_loop()
        give_up = loop.time() + HOLD_MAX_S
        while self._arriving or loop.time() - self._last_arrival < QUIET_S:
            if loop.time() >= give_up or self._stopping:
                return
            await asyncio.sleep(QUIET_S / 5)
