"""The journal's one writer: a thread that owns the write connection and commits in groups.

Callers hand it small write functions (each takes the connection and runs a few statements).
The thread takes every function waiting in its queue, runs them in one transaction — each in
its own savepoint, so one that fails rolls back alone and its caller gets the error — and
commits once. Only then are the callers' futures resolved: a caller that awaits its write knows
it is committed, and many instructions writing at the same moment share one commit instead of
queueing for one each. Functions run in the order they were submitted, so the journal's order
is the order in which the event loop recorded things.

Writes submitted from the event loop are collected for ``HAND_OVER_S`` and handed to the
thread as one batch: every hand-over wakes the thread, and a woken thread takes the GIL from
the loop for up to a switch interval (milliseconds), so one hand-over per write cost the loop
more than the writes themselves (measured: 2-3 ms of loop time per write).
"""

from __future__ import annotations

import asyncio
import logging
import queue
import sqlite3
import threading
from collections.abc import Callable
from concurrent.futures import Future
from dataclasses import dataclass
from typing import Any, TypeVar

logger = logging.getLogger(__name__)

T = TypeVar("T")
MAX_GROUP = 512  # writes committed together at most (bounds one transaction's time)
HAND_OVER_S = 0.002  # the loop collects writes this long before waking the writer


@dataclass
class _Job:
    write: Callable[[sqlite3.Connection], Any]
    future: Future[Any]


class JournalWriter:
    """Start with ``JournalWriter(conn)``; ``close()`` commits what is queued and stops."""

    def __init__(self, conn: sqlite3.Connection) -> None:
        self._conn = conn
        self._queue: queue.SimpleQueue[list[_Job] | None] = queue.SimpleQueue()
        self._pending: list[_Job] = []  # submitted on the loop, handed over at its next turn
        self._closed = False
        self.commits = 0
        self.writes = 0
        self._thread = threading.Thread(target=self._run, name="journal-writer", daemon=True)
        self._thread.start()

    def submit(self, write: Callable[[sqlite3.Connection], T], *, now: bool = False) -> Future[T]:
        """Queue ``write``; the future resolves once its group is committed.

        On the event loop (and unless ``now``) it joins the batch handed over at the loop's
        next turn; a caller about to block on the future passes ``now``."""
        if self._closed:
            raise RuntimeError("the journal is closed")
        future: Future[T] = Future()
        job = _Job(write, future)
        try:
            loop = None if now else asyncio.get_running_loop()
        except RuntimeError:
            loop = None
        if loop is None:
            self._flush()  # what the loop queued before goes first
            self._queue.put([job])
        else:
            if not self._pending:
                loop.call_later(HAND_OVER_S, self._flush)
            self._pending.append(job)
        return future

    def _flush(self) -> None:
        if self._pending:
            batch, self._pending = self._pending, []
            self._queue.put(batch)

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        self._flush()
        self._queue.put(None)
        self._thread.join()
        self._conn.close()

    def _run(self) -> None:
        while True:
            first = self._queue.get()
            if first is None:
                return
            group = list(first)
            stop = False
            while len(group) < MAX_GROUP:
                try:
                    batch = self._queue.get_nowait()
                except queue.Empty:
                    break
                if batch is None:
                    stop = True
                    break
                group += batch
            for start in range(0, len(group), MAX_GROUP):
                self._commit(group[start : start + MAX_GROUP])
            if stop:
                return

    def _commit(self, group: list[_Job]) -> None:
        results: list[tuple[_Job, Any, BaseException | None]] = []
        try:
            self._conn.execute("BEGIN IMMEDIATE")
            for job in group:
                self._conn.execute("SAVEPOINT job")
                try:
                    value = job.write(self._conn)
                except Exception as exc:
                    self._conn.execute("ROLLBACK TO job")
                    self._conn.execute("RELEASE job")
                    results.append((job, None, exc))
                else:
                    self._conn.execute("RELEASE job")
                    results.append((job, value, None))
            self._conn.execute("COMMIT")
        except Exception as exc:  # the commit itself failed: nothing of the group is written
            logger.exception("journal commit of %d writes failed", len(group))
            if self._conn.in_transaction:
                self._conn.execute("ROLLBACK")
            for job in group:
                job.future.set_exception(exc)
            return
        self.commits += 1
        self.writes += len(group)
        for job, value, error in results:
            if error is not None:
                job.future.set_exception(error)
            else:
                job.future.set_result(value)
