"""Leases with fencing tokens: which replica runs which office, and writes only it may make.

A row per office: its holder, its fencing token and when the lease expires. ``acquire``
takes a free or expired lease (the token goes up by one) or extends the caller's own;
``renew`` extends it while it is still the caller's (also just past its expiry when nobody
took it meanwhile: the token unchanged says nobody else held the office, so nothing was
lost); ``release`` frees it and keeps the row, so the token never goes back (a deleted row
would restart at 1, and the holder of an old token 1 could write again).

The token is what protects the data, not the expiry: a replica paused past its expiry (a long
GC, a stopped VM, a network cut) does not know it lost the office, so every write it makes
under the lease carries the token, and ``fence`` refuses one whose token is no longer the
office's (Kleppmann's fencing tokens). ``Journal.hold(lease)`` adds that check to every
journal write, in the write's own transaction; on PostgreSQL the check reads the row ``FOR
SHARE``, so a take-over waits for a write already checked to commit and the new holder reads
everything the old one wrote.

Time is the caller's clock (``clock``, epoch seconds): replicas of one deployment are
expected to keep their clocks in step (NTP); a lease of tens of seconds tolerates the
usual skew of milliseconds.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from assistantx.core.errors import JournalError, LeaseLostError
from assistantx.store.connection import Connection, database_errors
from assistantx.store.sqlite_store import Schema, SchemaError, SqliteStore

_TABLE = """
CREATE TABLE IF NOT EXISTS leases (
    office     TEXT PRIMARY KEY,
    holder     TEXT NOT NULL,
    token      BIGINT NOT NULL,
    expires_at {time} NOT NULL
)
"""
LEASES_SCHEMA = Schema(
    "leases",
    (_TABLE.format(time="REAL"),),
    postgres=(_TABLE.format(time="DOUBLE PRECISION"),),
)
FREE = ""  # the holder of a released lease


@dataclass(frozen=True)
class Lease:
    office: str
    holder: str
    token: int
    expires_at: float


class Leases:
    """``Leases.open(path)`` (the journal's SQLite file) or ``Leases.open(path,
    database_url=URL)``; ``close()`` it. Each call is one transaction, committed on return."""

    def __init__(self, db: SqliteStore, clock: Callable[[], float]) -> None:
        self._db = db
        self._clock = clock

    @classmethod
    def open(
        cls,
        path: Path,
        *,
        database_url: str | None = None,
        clock: Callable[[], float] = time.time,
    ) -> Leases:
        if database_url is None:
            where = str(path)
        else:
            from assistantx.store.postgres_store import PostgresStore, redact  # psycopg: here only

            where = redact(database_url)
        try:
            if database_url is None:
                return cls(SqliteStore.open(path, LEASES_SCHEMA), clock)
            return cls(PostgresStore.open_url(database_url, LEASES_SCHEMA), clock)
        except SchemaError as exc:
            raise JournalError(f"{where}: {exc}") from exc
        except database_errors() as exc:
            raise JournalError(f"{where}: cannot hold leases ({exc})") from exc

    def close(self) -> None:
        self._db.close()

    def acquire(self, office: str, holder: str, ttl_s: float) -> Lease | None:
        """The lease on ``office`` for ``ttl_s`` seconds; None while another holds it. A
        holder that still holds it keeps its token; a new holder gets the next one."""
        if not holder:
            raise ValueError("a lease needs a holder's name")
        now = self._clock()
        return self._db.call(_acquire(office, holder, now, now + ttl_s))

    def renew(self, lease: Lease, ttl_s: float) -> Lease:
        """``lease`` extended by ``ttl_s`` from now; LeaseLostError once another took it or
        it was released (a holder that lost its lease must acquire it again, with a new
        token)."""
        return self._db.call(_renew(lease, self._clock() + ttl_s))

    def release(self, lease: Lease) -> None:
        """Frees the office at once (a clean shutdown); nothing when it is no longer ours."""
        self._db.call(_release(lease))

    def holders(self) -> list[Lease]:
        """Every office's lease, held or not (a released one has holder ``""``)."""
        rows = self._db.call(
            lambda db: db.execute("SELECT * FROM leases ORDER BY office").fetchall()
        )
        return [_lease(r) for r in rows]


def _lease(row: Any) -> Lease:
    return Lease(
        office=row["office"],
        holder=row["holder"],
        token=int(row["token"]),
        expires_at=float(row["expires_at"]),
    )


def _acquire(
    office: str, holder: str, now: float, expires_at: float
) -> Callable[[Connection], Lease | None]:
    def write(db: Connection) -> Lease | None:
        # One statement, so two replicas racing for a free office cannot both win: the
        # update runs only on a free or expired row, or on the caller's own.
        row = db.execute(
            "INSERT INTO leases (office, holder, token, expires_at) VALUES (?, ?, 1, ?)"
            " ON CONFLICT (office) DO UPDATE SET holder=excluded.holder,"
            " expires_at=excluded.expires_at,"
            " token=CASE WHEN leases.holder=excluded.holder AND leases.expires_at > ?"
            " THEN leases.token ELSE leases.token + 1 END"
            " WHERE leases.expires_at <= ? OR leases.holder=excluded.holder"
            " RETURNING office, holder, token, expires_at",
            (office, holder, expires_at, now, now),
        ).fetchone()
        return None if row is None else _lease(row)

    return write


def _renew(lease: Lease, expires_at: float) -> Callable[[Connection], Lease]:
    def write(db: Connection) -> Lease:
        row = db.execute(
            "UPDATE leases SET expires_at=? WHERE office=? AND holder=? AND token=?"
            " RETURNING office, holder, token, expires_at",
            (expires_at, lease.office, lease.holder, lease.token),
        ).fetchone()
        if row is None:
            raise LeaseLostError(f"the lease on office {lease.office!r} was lost")
        return _lease(row)

    return write


def _release(lease: Lease) -> Callable[[Connection], None]:
    def write(db: Connection) -> None:
        db.execute(
            "UPDATE leases SET holder=?, expires_at=0 WHERE office=? AND holder=? AND token=?",
            (FREE, lease.office, lease.holder, lease.token),
        )

    return write


def fence(lease: Lease, *, postgres: bool) -> Callable[[Connection], None]:
    """The check a write under ``lease`` runs first, in its own transaction: LeaseLostError
    when the office's token is no longer the lease's (taken over, or released)."""
    lock = " FOR SHARE" if postgres else ""  # SQLite: the writer already holds the file

    def check(db: Connection) -> None:
        row = db.execute(
            f"SELECT holder, token FROM leases WHERE office=?{lock}", (lease.office,)
        ).fetchone()
        if row is None or (row["holder"], int(row["token"])) != (lease.holder, lease.token):
            raise LeaseLostError(
                f"a write under a stale lease on office {lease.office!r} was refused"
            )

    return check
