"""The store machine of ``sqlite_store`` on PostgreSQL: one connection, one thread, group commit.

``PostgresStore`` inherits the queue, the writer thread and its group commit (one transaction
per group, a savepoint per call) from ``SqliteStore``; only the connection differs. Why one
connection and a thread rather than an async pool: every store's calls are small synchronous
functions that take a connection (written once for both backends), and one writer per store
keeps the order of its writes the order its callers made them, as on SQLite. psycopg 3 is the
driver (the one maintained for PostgreSQL by its own community, typed, with a binary wheel
that brings its libpq); SQLAlchemy Core and Alembic would add an expression language and a
second migration system to stores that are a few dozen plain statements each.

``PgConnection`` lets the stores' SQL (``?`` parameters, rows by name or position) run as
written. ``migrate_postgres`` brings a ``Schema`` up to date like ``sqlite_store.migrate``,
holding a transaction-level advisory lock, so replicas that start together migrate once.
"""

from __future__ import annotations

import functools
import logging
import zlib
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import psycopg
from psycopg import pq
from psycopg.conninfo import conninfo_to_dict, make_conninfo

from assistantx.store.connection import transaction
from assistantx.store.sqlite_store import Schema, SchemaError, SqliteStore

logger = logging.getLogger(__name__)

CONNECT_TIMEOUT_S = 10
# A transaction left open by a process that stopped (SIGSTOP, a frozen VM, a debugger) keeps
# its row locks: a paused replica's journal write holds the lease row FOR SHARE, and the
# standby's take-over would wait on it for as long as the pause lasts. The server ends such a
# session after this long idle inside a transaction; its uncommitted writes are dropped, which
# is what fencing wants from a replica that stopped mid-write. The stores' transactions are
# short runs of statements from one thread, idle between them for microseconds.
IDLE_IN_TRANSACTION_TIMEOUT_S = 5


class Row(tuple[Any, ...]):
    """A row read by position (``row[0]``) or by column name (``row["seq"]``), like sqlite3's."""

    _index: dict[str, int]

    def __getitem__(self, key: Any) -> Any:
        if isinstance(key, str):
            return tuple.__getitem__(self, self._index[key])
        return tuple.__getitem__(self, key)

    def keys(self) -> list[str]:
        return list(self._index)


def _row_factory(cursor: psycopg.Cursor[Any]) -> Callable[[Sequence[Any]], Row]:
    index = {column.name: n for n, column in enumerate(cursor.description or ())}

    def make(values: Sequence[Any]) -> Row:
        row = Row(values)
        row._index = index
        return row

    return make


@functools.lru_cache(maxsize=512)
def _to_pyformat(sql: str) -> str:
    """``?`` parameters to psycopg's ``%s`` (a literal ``%`` doubled). The stores' statements
    hold no ``?`` inside a string literal."""
    return sql.replace("%", "%%").replace("?", "%s")


class PgConnection:
    """A psycopg connection in autocommit mode: a statement outside ``BEGIN`` commits alone;
    ``BEGIN``/``COMMIT`` sent as statements group them, as on the SQLite connection.

    A connection the server dropped (a restart, a fail-over, an idle timeout) fails the
    statement that finds it broken; the next statement outside a transaction connects again."""

    def __init__(self, conn: psycopg.Connection[Row], url: str) -> None:
        self.raw = conn
        self._url = url
        self._closed = False

    def execute(self, sql: str, parameters: Sequence[Any] = (), /) -> psycopg.Cursor[Row]:
        if self.raw.broken and not self._closed:
            logger.warning("%s: the connection was lost; connecting again", redact(self._url))
            self.raw = _connect_raw(self._url)
        if parameters:
            return self.raw.execute(_to_pyformat(sql), tuple(parameters))
        return self.raw.execute(sql)

    @property
    def in_transaction(self) -> bool:
        # UNKNOWN (a broken connection) is no transaction: there is nothing to roll back.
        return self.raw.info.transaction_status in (
            pq.TransactionStatus.INTRANS,
            pq.TransactionStatus.INERROR,
            pq.TransactionStatus.ACTIVE,
        )

    def close(self) -> None:
        self._closed = True
        self.raw.close()


def redact(url: str) -> str:
    """The URL without its password, for messages and logs."""
    try:
        params = conninfo_to_dict(url)
    except psycopg.ProgrammingError:
        return "postgresql://(an unreadable URL)"
    params.pop("password", None)
    host, port, name = params.get("host", ""), params.get("port", ""), params.get("dbname", "")
    user = f"{params['user']}@" if params.get("user") else ""
    return f"postgresql://{user}{host}{':' + str(port) if port else ''}/{name}"


def _connect_raw(url: str) -> psycopg.Connection[Row]:
    conninfo = make_conninfo(url, connect_timeout=CONNECT_TIMEOUT_S, application_name="assistantx")
    conn = psycopg.connect(conninfo, autocommit=True, row_factory=_row_factory)
    conn.execute(
        "SELECT set_config('idle_in_transaction_session_timeout', %s, false)",
        (f"{IDLE_IN_TRANSACTION_TIMEOUT_S * 1000}",),
    )
    return conn


def connect_postgres(url: str) -> PgConnection:
    """A connection to ``url`` (``postgresql://user:password@host:port/db``), autocommit."""
    return PgConnection(_connect_raw(url), url)


class PostgresStore(SqliteStore):
    """Open with ``PostgresStore.open(url, schema)``; ``close()`` commits what is queued."""

    BEGIN = "BEGIN"

    @classmethod
    def open_url(cls, url: str, schema: Schema) -> PostgresStore:
        """Connect and bring ``schema`` up to date. Raises ``psycopg.Error`` for a database
        that cannot be reached or used and ``SchemaError`` for one newer than ``schema``."""
        conn = connect_postgres(url)
        try:
            migrate_postgres(conn, schema)
        except BaseException:
            conn.close()
            raise
        store = cls(conn, Path(conn.raw.info.dbname), schema.name)
        store.where = redact(url)
        return store


def _lock_key(name: str) -> int:
    """A stable 32-bit key per store for ``pg_advisory_xact_lock``."""
    return zlib.crc32(f"assistantx-schema-{name}".encode())


def _stored_version(conn: PgConnection, schema: Schema) -> int:
    row = conn.execute(
        "SELECT version FROM store_versions WHERE store=?", (schema.name,)
    ).fetchone()
    found = 0 if row is None else int(row[0])
    if found > schema.version:
        raise SchemaError(
            f"{schema.name} schema {found}, this version reads {schema.version} at most"
        )
    return found


def migrate_postgres(conn: PgConnection, schema: Schema) -> int:
    """Run the PostgreSQL migrations ``schema`` lacks in one transaction; returns the version
    before. Concurrent callers (replicas starting together) wait for each other's lock."""
    if len(schema.postgres) != schema.version:
        raise SchemaError(
            f"{schema.name} has {len(schema.postgres)} PostgreSQL migrations for"
            f" {schema.version} versions: it cannot run on PostgreSQL"
        )
    with transaction(conn):
        conn.execute("SELECT pg_advisory_xact_lock(?)", (_lock_key(schema.name),))
        conn.execute(
            "CREATE TABLE IF NOT EXISTS store_versions"
            " (store TEXT PRIMARY KEY, version INTEGER NOT NULL)"
        )
        found = _stored_version(conn, schema)
        for migration in schema.postgres[found:]:
            if isinstance(migration, str):
                conn.execute(migration)
            else:
                migration(conn)
        if found != schema.version:
            conn.execute(
                "INSERT INTO store_versions VALUES (?, ?)"
                " ON CONFLICT (store) DO UPDATE SET version=excluded.version",
                (schema.name, schema.version),
            )
    return found
