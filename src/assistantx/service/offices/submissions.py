"""Submissions and reads for an office another replica runs, through the shared database.

With several offices on replicas, a request may reach a replica that does not run its office.
Reads need no runtime: the office's journal is in the shared database, so ``OfficeDesk``
answers ``GET /v1/instructions`` and ``GET /v1/instructions/{id}`` from it. A submission is
journaled there as ``queued`` (the very row the owner's own route writes) and, in the same
transaction, ``NOTIFY``-ed on the office's channel (``channel``); the owning replica
``LISTEN``s on it (``SubmissionListener``) and starts what it is told of. A submission made
while no replica runs the office, or before the owner listens, is started by the owner's
start-up, which starts every instruction journaled and never started.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from assistantx.core.office import Office, PersonId
from assistantx.memory.resolve import Resolver
from assistantx.runtime.assistant import new_instruction_id
from assistantx.service.errors import journaled_instruction, unknown_instruction
from assistantx.store.journal import InstructionRecord, Journal

if TYPE_CHECKING:  # psycopg is imported by the listener's start: only replicas listen, and
    import psycopg  # importing it cost every embedded (SQLite) start ~0.06-0.1 CPU-s

logger = logging.getLogger(__name__)


def channel(office_id: str) -> str:
    """The office's PostgreSQL channel for submissions journaled by another replica."""
    return f"assistantx_submitted_{office_id}"


class OfficeDesk:
    """Reads and submissions of an office run elsewhere: the routes' ``ServiceRuntime``
    calls, on the office's journal. ``close()`` it."""

    def __init__(self, office_id: str, office: Office, journal: Journal) -> None:
        self.office_id = office_id
        self.office = office
        self.resolver = Resolver(office)
        self.journal = journal

    def close(self) -> None:
        self.journal.close()

    async def submit(self, person: PersonId, text: str) -> InstructionRecord:
        """Journal the instruction for the owning replica, which is told at commit. (The
        owner's per-person rate applies to what reaches the owner itself.)"""
        return await self.journal.acreate_instruction(
            new_instruction_id(), person, text, time.time(), notify=channel(self.office_id)
        )

    def instruction(self, instruction_id: str) -> InstructionRecord:
        return journaled_instruction(self.journal, instruction_id)

    unknown_instruction = staticmethod(unknown_instruction)


class SubmissionListener:
    """``LISTEN``s on an office's channel and hands each id told to ``pick_up`` (on the event
    loop); ``start()`` returns once it listens, ``stop()`` closes the connection."""

    def __init__(self, url: str, office_id: str, pick_up: Callable[[str], None]) -> None:
        self._url = url
        self._channel = channel(office_id)
        self._pick_up = pick_up
        self._conn: psycopg.AsyncConnection[tuple[object, ...]] | None = None
        self._task: asyncio.Task[None] | None = None

    async def start(self) -> None:
        import psycopg
        from psycopg import sql
        from psycopg.conninfo import make_conninfo

        conninfo = make_conninfo(self._url, application_name="assistantx-submissions")
        self._conn = await psycopg.AsyncConnection.connect(conninfo, autocommit=True)
        await self._conn.execute(sql.SQL("LISTEN {}").format(sql.Identifier(self._channel)))
        self._task = asyncio.create_task(self._listen(self._conn), name="submission-listener")

    async def _listen(self, conn: psycopg.AsyncConnection[tuple[object, ...]]) -> None:
        import psycopg  # imported already by start()

        try:
            async for note in conn.notifies():
                self._pick_up(note.payload)
        except psycopg.Error as exc:
            # The owner still starts such submissions at its next start-up.
            logger.warning("stopped listening for submissions on %s: %s", self._channel, exc)

    async def stop(self) -> None:
        if self._task is not None:
            self._task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._task
            self._task = None
        if self._conn is not None:
            await self._conn.close()
            self._conn = None
