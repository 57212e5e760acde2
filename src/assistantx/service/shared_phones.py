"""The simulated people's phones in the replicas' database, so they outlive a replica.

With one process, ``colleagues.CodePhones`` keeps the QR payloads simulated people hold in an
owner-only file of the data folder. Replicas each have their own data folder, so after a
takeover the new replica's simulated people held nothing: a person sent a deposit code by the
killed replica never came to the locker, the wait timed out and a second code went out (real
people keep their phones, and a networked lock keeps its codes, when a replica dies). Here the
payloads live in one table of the shared database, apart from the journal (which never holds
a payload); the new replica reads them back and arms its in-process lock with the live ones.

A write carries the office lease's fencing check (``store.leases.fence``), in its own
transaction: a replica that lost the office cannot take the codes out of people's hands.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from assistantx.service.colleagues import phone_entries
from assistantx.sim.office import HeldCode
from assistantx.store.connection import Connection
from assistantx.store.sqlite_store import Schema

if TYPE_CHECKING:
    from assistantx.store.postgres_store import PostgresStore

_TABLE = "CREATE TABLE IF NOT EXISTS sim_phones (ref TEXT PRIMARY KEY, payload TEXT NOT NULL)"
PHONES_SCHEMA = Schema("sim_phones", (_TABLE,), postgres=(_TABLE,))

Fence = Callable[[Connection], None]


class SharedPhones:
    """``CodePhones``'s ``save`` and ``load`` on the replicas' PostgreSQL; ``close()`` it."""

    def __init__(self, db: PostgresStore, fence: Fence | None = None) -> None:
        self._db = db
        self.fence = fence  # set once the office's lease is held
        self._written: dict[str, str] | None = None

    @classmethod
    def open(cls, database_url: str) -> SharedPhones:
        from assistantx.store.postgres_store import PostgresStore  # psycopg: replicas only

        return cls(PostgresStore.open_url(database_url, PHONES_SCHEMA))

    def close(self) -> None:
        self._db.close()

    def save(self, codes: list[HeldCode]) -> None:
        """Blocks until committed: the checkpoint that names these codes is written next, and
        a replica that reads that checkpoint must find their payloads."""
        held = phone_entries(codes)
        if held == self._written:
            return
        fence = self.fence

        def write(db: Connection) -> None:
            if fence is not None:
                fence(db)
            db.execute("DELETE FROM sim_phones")
            for ref, payload in held.items():
                db.execute("INSERT INTO sim_phones (ref, payload) VALUES (?, ?)", (ref, payload))

        self._db.call(write)
        self._written = held

    def load(self) -> dict[str, str]:
        rows = self._db.call(
            lambda db: db.execute("SELECT ref, payload FROM sim_phones").fetchall()
        )
        return {str(r["ref"]): str(r["payload"]) for r in rows}
