"""What a store's SQL sees of its database, whichever backend holds it.

Every store writes its statements once, in the dialect both engines share: ``?`` parameters,
``INSERT ... ON CONFLICT``, ``RETURNING seq`` for a new row's number (SQLite since 3.35), rows
read by column name or position. ``sqlite3.Connection`` is a ``Connection`` as it is;
``postgres_store.PgConnection`` adapts psycopg's to it. What the engines do not share (column
types, the autoincrement key, the store's migrations) is spelled once per backend in its
``Schema``.
"""

from __future__ import annotations

import sqlite3
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Protocol


class Cursor(Protocol):
    """The part of a DB-API cursor the stores use (no ``lastrowid``: use ``RETURNING``)."""

    @property
    def rowcount(self) -> int: ...

    def fetchone(self) -> Any: ...

    def fetchall(self) -> list[Any]: ...

    def __iter__(self) -> Iterator[Any]: ...


class Connection(Protocol):
    """One database connection; a row supports ``row["column"]`` and ``row[0]``."""

    def execute(self, sql: str, parameters: Sequence[Any] = ..., /) -> Cursor: ...


class TransactedConnection(Connection, Protocol):
    """A connection that says whether a transaction is open (``sqlite3.Connection`` and
    ``postgres_store.PgConnection`` both do)."""

    @property
    def in_transaction(self) -> bool: ...


@contextmanager
def transaction(conn: TransactedConnection, begin: str = "BEGIN") -> Iterator[None]:
    """One transaction around the block: ``begin``, then COMMIT; on any error, COMMIT's
    included, ROLLBACK where one is still open, and the error raised again. BaseException:
    an interrupted migration leaves nothing half-done either."""
    conn.execute(begin)
    try:
        yield
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:
            conn.execute("ROLLBACK")
        raise


def integrity_errors() -> tuple[type[Exception], ...]:
    """A constraint refused a write (a taken key), from either backend.

    psycopg's class only once psycopg is loaded: a service on SQLite never imports it (a
    third of a CPU-second at start), and no psycopg error can be raised before it is."""
    psycopg = sys.modules.get("psycopg")
    if psycopg is None:
        return (sqlite3.IntegrityError,)
    return (sqlite3.IntegrityError, psycopg.IntegrityError)


def database_errors() -> tuple[type[Exception], ...]:
    """Any error of either backend (psycopg's once it is loaded, as above)."""
    psycopg = sys.modules.get("psycopg")
    if psycopg is None:
        return (sqlite3.Error,)
    return (sqlite3.Error, psycopg.Error)


POSTGRES_SCHEMES = ("postgresql://", "postgres://")


def is_postgres_url(location: str | Path | None) -> bool:
    """Whether ``location`` names a PostgreSQL database rather than a SQLite file."""
    return isinstance(location, str) and location.startswith(POSTGRES_SCHEMES)
