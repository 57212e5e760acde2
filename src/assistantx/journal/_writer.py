"""The journal's one writer: a thread that owns the write connection and commits in groups.

Callers hand it small write functions (each takes the connection and runs a few statements).
The thread takes every function waiting in its queue, runs them in one transaction — each in
its own savepoint, so one that fails rolls back alone and its caller gets the error — and
commits once. Only then are the callers' futures resolved: a caller that awaits its write knows
it is committed, and many instructions writing at the same moment share one commit instead of
queueing for one each. Functions run in the order they were submitted, so the journal's order
is the order in which the event loop recorded things.
"""

from __future__ import annotations

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


@dataclass
class _Job:
    write: Callable[[sqlite3.Connection], Any]
    future: Future[Any]


class JournalWriter:
    """Start with ``JournalWriter(conn)``; ``close()`` commits what is queued and stops."""

    def __init__(self, conn: sqlite3.Connection) -> None:
        self._conn = conn
        self._queue: queue.SimpleQueue[_Job | None] = queue.SimpleQueue()
        self._closed = False
        self.commits = 0
        self.writes = 0
        self._thread = threading.Thread(target=self._run, name="journal-writer", daemon=True)
        self._thread.start()

    def submit(self, write: Callable[[sqlite3.Connection], T]) -> Future[T]:
        """Queue ``write``; the future resolves once its group is committed."""
        if self._closed:
            raise RuntimeError("the journal is closed")
        future: Future[T] = Future()
        self._queue.put(_Job(write, future))
        return future

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        self._queue.put(None)
        self._thread.join()
        self._conn.close()

    def _run(self) -> None:
        while True:
            first = self._queue.get()
            if first is None:
                return
            group = [first]
            stop = False
            while len(group) < MAX_GROUP:
                try:
                    job = self._queue.get_nowait()
                except queue.Empty:
                    break
                if job is None:
                    stop = True
                    break
                group.append(job)
            self._commit(group)
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
