"""One SQLite file owned by one thread: open with our pragmas, migrate by version, run calls.

Every store of the service (the journal, the survey store, the Matrix event store) opens its
file through ``SqliteStore.open``. The store's one connection belongs to one thread; callers
hand it small functions (each takes the connection and runs a few statements) and get a
future. The thread takes every function waiting in its queue, runs them in one transaction —
each in its own savepoint, so one that fails rolls back alone and its caller gets the
exception — and commits once. Only then are the futures resolved: a caller that has its
result knows its write is committed, and many writes arriving together share one commit
(group commit) instead of queueing for one each. Functions run in the order submitted, so a
store's order is the order in which its callers recorded things. Reads that must see the
store's writes go through the same queue (they are ordered after them). A call once submitted
is run and committed even when its caller stops waiting (a cancelled task).

Async callers ``await store.acall(fn)``: the event loop serves others while the thread works.
Sync callers (the CLI, start-up, a worker thread, tests) use ``store.call(fn)``, which blocks
the calling thread until the commit — on the event loop that stalls every other coroutine, so
code on the loop awaits ``acall`` instead.

Calls submitted from the event loop are collected for ``HAND_OVER_S`` and handed to the
thread as one batch: every hand-over wakes the thread, and a woken thread takes the GIL from
the loop for up to a switch interval (milliseconds), so one hand-over per call cost the loop
more than the writes themselves (measured on the journal: 2-3 ms of loop time per write).

The schema: a store names itself and lists its migrations; migration ``i`` takes the store
from version ``i`` to ``i + 1``. The version of each store lives in the file's
``store_versions`` table (several stores may share a file, as the survey store shares the
journal's), and ``open`` runs the missing migrations in one transaction, so a failing one
leaves the file as it was. A file written by a newer version (more migrations than this code
knows) is refused with ``SchemaError``.
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
from pathlib import Path
from typing import Any, Literal, TypeVar

from assistantx.store.connection import Connection, transaction

logger = logging.getLogger(__name__)

T = TypeVar("T")
MAX_GROUP = 512  # calls committed together at most (bounds one transaction's time)
HAND_OVER_S = 0.002  # the loop collects calls this long before waking the thread
BUSY_TIMEOUT_MS = 5000  # another connection on the file (a second store, an operator's shell)

Migration = str | Callable[[sqlite3.Connection], None]
"""SQL statements (separated by ``;``), or a function run on the connection."""
PgMigration = str | Callable[[Connection], None]
"""The same for PostgreSQL (``postgres_store``): statements, or a function on the connection."""
Synchronous = Literal["OFF", "NORMAL", "FULL", "EXTRA"]


class SchemaError(Exception):
    """The file's schema is newer than this code, or its version row is unreadable."""


class StoreClosedError(RuntimeError):
    """A call submitted after ``close``."""


@dataclass(frozen=True)
class Schema:
    """``name``: the store's row in ``store_versions``; ``migrations[i]``: version i → i+1.

    ``postgres[i]`` is migration ``i`` for PostgreSQL: the same tables in its types (a store
    without them runs on SQLite only). Both lists grow together, so a version number means
    the same schema on both backends."""

    name: str
    migrations: tuple[Migration, ...]
    postgres: tuple[PgMigration, ...] = ()

    @property
    def version(self) -> int:
        return len(self.migrations)


@dataclass
class _Job:
    fn: Callable[[Any], Any]
    future: Future[Any]


class SqliteStore:
    """Open with ``SqliteStore.open(path, schema)``; ``close()`` commits what is queued.

    ``postgres_store.PostgresStore`` is the same machine on a PostgreSQL connection."""

    BEGIN = "BEGIN IMMEDIATE"  # takes the file's write lock now, not at the first write

    def __init__(self, conn: Any, path: Path, name: str) -> None:
        self._conn = conn
        self.path = path
        self.where = str(path)  # for messages: the file, or the database's redacted URL
        self._queue: queue.SimpleQueue[list[_Job] | None] = queue.SimpleQueue()
        # Submitted on an event loop, handed over at its next turn. The lock orders a sync
        # submit (any thread) after what the loop queued, and nothing after ``close``.
        self._pending: list[_Job] = []
        self._pending_loop: asyncio.AbstractEventLoop | None = None
        self._lock = threading.Lock()
        self._closed = False
        self.commits = 0
        self.writes = 0  # calls committed
        self._thread = threading.Thread(target=self._run, name=f"sqlite-{name}", daemon=True)
        self._thread.start()

    @classmethod
    def open(
        cls,
        path: Path,
        schema: Schema,
        *,
        synchronous: Synchronous = "NORMAL",
        foreign_keys: bool = False,
    ) -> SqliteStore:
        """Open (or create) ``path`` in WAL mode and bring ``schema`` up to date.

        ``synchronous``: NORMAL keeps every commit through a crash of the process (kill -9),
        FULL also through a power loss (an fsync per commit). Raises ``sqlite3.Error`` for a
        file SQLite cannot use and ``SchemaError`` for one newer than ``schema``."""
        path.parent.mkdir(parents=True, exist_ok=True)
        conn = connect(path, synchronous=synchronous, foreign_keys=foreign_keys)
        try:
            conn.execute("PRAGMA journal_mode=WAL")
            migrate(conn, schema)
        except BaseException:
            conn.close()
            raise
        return cls(conn, path, schema.name)

    # -- calls -----------------------------------------------------------------------------
    def submit(self, fn: Callable[[Any], T], *, now: bool = False) -> Future[T]:
        """Queue ``fn``; the future resolves once its group is committed.

        On an event loop (and unless ``now``) it joins the batch handed over at the loop's
        next turn; a caller about to block on the future passes ``now``."""
        future: Future[T] = Future()
        # Running from the start, so it cannot be cancelled: a caller that stops waiting
        # (its task cancelled, which cancels the future it awaits) still has its write
        # committed in order, and the thread never sets the result of a cancelled future
        # (that raises, and killed the journal's old writer thread, hanging every later call).
        future.set_running_or_notify_cancel()
        job = _Job(fn, future)
        try:
            loop = None if now else asyncio.get_running_loop()
        except RuntimeError:
            loop = None
        with self._lock:
            if self._closed:
                raise StoreClosedError(f"{self.where}: the store is closed")
            if loop is not None and self._pending_loop in (None, loop):
                if not self._pending:
                    self._pending_loop = loop
                    loop.call_later(HAND_OVER_S, self._flush)
                self._pending.append(job)
            else:
                self._flush_locked()  # what a loop queued before goes first
                self._queue.put([job])
        return future

    def call(self, fn: Callable[[Any], T]) -> T:
        """Run ``fn`` on the store's thread and wait until it is committed (blocks)."""
        return self.submit(fn, now=True).result()

    async def acall(self, fn: Callable[[Any], T]) -> T:
        """Like ``call``, but the event loop serves others meanwhile."""
        return await asyncio.wrap_future(self.submit(fn))

    def close(self) -> None:
        """Commit what is queued, stop the thread, close the file; a second call does nothing."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._flush_locked()
            self._queue.put(None)
        self._thread.join()
        self._conn.close()

    async def aclose(self) -> None:
        """``close`` on a worker thread, so the loop is not held while the queue drains."""
        await asyncio.to_thread(self.close)

    def _flush(self) -> None:
        with self._lock:
            self._flush_locked()

    def _flush_locked(self) -> None:
        if self._pending:
            batch, self._pending, self._pending_loop = self._pending, [], None
            self._queue.put(batch)

    # -- the thread ------------------------------------------------------------------------
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
            self._conn.execute(self.BEGIN)
            for job in group:
                self._conn.execute("SAVEPOINT job")
                try:
                    value = job.fn(self._conn)
                except Exception as exc:
                    self._conn.execute("ROLLBACK TO job")
                    self._conn.execute("RELEASE job")
                    results.append((job, None, exc))
                else:
                    self._conn.execute("RELEASE job")
                    results.append((job, value, None))
            self._conn.execute("COMMIT")
        except Exception as exc:  # the commit itself failed: nothing of the group is written
            logger.exception("%s: commit of %d calls failed", self.where, len(group))
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


def connect(
    path: Path, *, synchronous: Synchronous = "NORMAL", foreign_keys: bool = False
) -> sqlite3.Connection:
    """A connection with our pragmas, transactions explicit (``BEGIN``), rows by name.

    Also for a store's second, read-only connection (WAL lets it read beside the writer)."""
    conn = sqlite3.connect(path, isolation_level=None, check_same_thread=False)
    conn.row_factory = sqlite3.Row
    try:
        conn.execute(f"PRAGMA synchronous={synchronous}")
        conn.execute(f"PRAGMA busy_timeout={BUSY_TIMEOUT_MS}")
        conn.execute(f"PRAGMA foreign_keys={'ON' if foreign_keys else 'OFF'}")
    except BaseException:
        conn.close()
        raise
    return conn


def migrate(conn: sqlite3.Connection, schema: Schema) -> int:
    """Run the migrations ``schema`` lacks in one transaction; returns the version before."""
    with transaction(conn, "BEGIN IMMEDIATE"):
        conn.execute(
            "CREATE TABLE IF NOT EXISTS store_versions"
            " (store TEXT PRIMARY KEY, version INTEGER NOT NULL)"
        )
        found = _stored_version(conn, schema)
        for migration in schema.migrations[found:]:
            if isinstance(migration, str):
                execute_script(conn, migration)
            else:
                migration(conn)
        if found != schema.version:
            conn.execute(
                "INSERT OR REPLACE INTO store_versions VALUES (?, ?)",
                (schema.name, schema.version),
            )
    return found


def _stored_version(conn: sqlite3.Connection, schema: Schema) -> int:
    row = conn.execute(
        "SELECT version FROM store_versions WHERE store=?", (schema.name,)
    ).fetchone()
    found = 0 if row is None else row[0]
    if not isinstance(found, int) or found < 0:
        raise SchemaError(f"{schema.name} schema version {found!r} is not a version")
    if found > schema.version:
        raise SchemaError(
            f"{schema.name} schema {found}, this version reads {schema.version} at most"
        )
    return found


def execute_script(conn: sqlite3.Connection, script: str) -> None:
    """Run the statements of ``script`` inside the current transaction (``executescript``
    would commit it first), split at the ``;`` that end statements."""
    current = ""
    for piece in script.split(";"):
        current += piece + ";"
        if sqlite3.complete_statement(current):
            if current.strip(" \n\t;"):
                conn.execute(current)
            current = ""
    if current.strip(" \n\t;"):
        raise SchemaError(f"an incomplete SQL statement: {current.strip()[:60]!r}")
