"""The durable memory of inbound delivery: which events and transactions were already taken in,
which are not yet handled, and where each poller stopped.

``EventStore`` is the protocol the push routers and the poller use; ``SqliteEventStore`` keeps
it in one SQLite file in WAL mode with ``synchronous=FULL``, so once ``accept`` returns, the
messages survive a crash and a push may be acknowledged; given a ``database_url`` it keeps it
in that PostgreSQL database instead (the journal's, with ``ASSISTANTX_DATABASE_URL``), with
the same statements (``store.connection``). The service may later replace it with
its journal.

It also keeps the bot's own state, which must survive a restart: each person's DM room, the
transaction id of every outbound part (random, never reused, so the homeserver never takes a
new message for a repeat of an old one), which sent event asked which question, and the
``mxc://`` reference of each file a person sent (so it can be forwarded later).

The same store deduplicates across paths: an event taken in by the application-service push
is not taken in again by the /sync poller (and vice versa), because ``accept`` keeps only
``(platform, event_id)`` pairs it has never seen, in one SQL transaction.
"""

from __future__ import annotations

import uuid
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Protocol, TypeVar

from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import InboundMessage
from assistantx.store.connection import Connection, database_errors
from assistantx.store.sqlite_store import Schema, SchemaError, SqliteStore, StoreClosedError

T = TypeVar("T")


class EventStore(Protocol):
    """Durable dedup of inbound events and transactions, plus poller positions."""

    async def transaction_seen(self, txn_id: str) -> bool:
        """Whether a pushed transaction was already accepted."""
        ...

    async def event_seen(self, platform: str, event_id: str) -> bool:
        """Whether an event was already accepted (by any path)."""
        ...

    async def accept(
        self,
        messages: Sequence[InboundMessage],
        *,
        txn_id: str | None = None,
        sync_key: str | None = None,
        sync_token: str | None = None,
    ) -> list[InboundMessage]:
        """Durably record, in one atomic write, the messages never seen before, the transaction
        id and the poller position; return the new messages in the order given."""
        ...

    async def mark_handled(self, platform: str, event_id: str) -> None:
        """The consumer finished with an event; it is no longer replayed on start."""
        ...

    async def unhandled(self) -> list[InboundMessage]:
        """Accepted but not yet handled messages, oldest first (replayed after a restart)."""
        ...

    async def sync_token(self, sync_key: str) -> str | None:
        """Where the poller named ``sync_key`` stopped, or None before its first run."""
        ...

    async def claim(self, platform: str, event_ids: Sequence[str]) -> list[str]:
        """Record events answered without a message (a notice sent back); return the new ones."""
        ...

    async def dm_rooms(self) -> dict[str, str]:
        """person id → the DM room recorded for them."""
        ...

    async def set_dm_room(self, person: str, room_id: str | None) -> None:
        """Record (or, with None, forget) ``person``'s DM room."""
        ...

    async def outbound_part(
        self, key: str, part: int, digest: str, *, room_id: str, instruction_id: str | None
    ) -> OutboundPart:
        """The transaction of one part of an outbound message: the recorded one when the same
        key sent the same content to the same room before (a retry), else a fresh random id."""
        ...

    async def part_sent(self, txn_id: str, event_id: str, question_id: str | None) -> None: ...

    async def close_instruction(self, instruction_id: str) -> None:
        """The instruction ended: its keys never deduplicate a later send again."""
        ...

    async def question_of(self, event_id: str) -> str | None:
        """The question a sent event asked ("" for a sent event that asked nothing)."""
        ...

    async def remember_media(self, item: str, ref: str, name: str, mime: str) -> None: ...

    async def media(self, item: str) -> tuple[str, str, str] | None:
        """(mxc:// reference, name, mime type) of the latest file recorded as ``item``."""
        ...

    async def close(self) -> None: ...


@dataclass(frozen=True)
class OutboundPart:
    txn_id: str
    event_id: str | None  # set once the homeserver took it


_SCHEMA = """
CREATE TABLE IF NOT EXISTS inbound_events (
    seq INTEGER PRIMARY KEY AUTOINCREMENT,
    platform TEXT NOT NULL,
    event_id TEXT NOT NULL,
    message TEXT NOT NULL,
    accepted_at TEXT NOT NULL,
    handled INTEGER NOT NULL DEFAULT 0,
    UNIQUE (platform, event_id)
);
CREATE TABLE IF NOT EXISTS transactions (
    txn_id TEXT PRIMARY KEY,
    accepted_at TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS dm_rooms (
    person TEXT PRIMARY KEY,
    room_id TEXT NOT NULL,
    saved_at TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS outbound_parts (
    key TEXT NOT NULL,
    part INTEGER NOT NULL,
    digest TEXT NOT NULL,
    room_id TEXT NOT NULL,
    instruction_id TEXT,
    closed INTEGER NOT NULL DEFAULT 0,
    txn_id TEXT NOT NULL UNIQUE,
    event_id TEXT,
    question_id TEXT,
    saved_at TEXT NOT NULL,
    PRIMARY KEY (key, part)
);
CREATE INDEX IF NOT EXISTS outbound_parts_event ON outbound_parts (event_id);
CREATE TABLE IF NOT EXISTS media (
    item TEXT PRIMARY KEY,
    ref TEXT NOT NULL,
    name TEXT NOT NULL,
    mime TEXT NOT NULL,
    saved_at TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS sync_tokens (
    sync_key TEXT PRIMARY KEY,
    token TEXT NOT NULL,
    saved_at TEXT NOT NULL
);
"""
_POSTGRES_SCHEMA = _SCHEMA.replace(
    "INTEGER PRIMARY KEY AUTOINCREMENT", "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"
)
EVENT_SCHEMA = Schema("matrix_events", (_SCHEMA,), postgres=(_POSTGRES_SCHEMA,))


class SqliteEventStore:
    """``EventStore`` in one SQLite file. Calls run on the store's own thread, in order, each
    one transaction (``core.sqlite_store``); the event loop awaits them."""

    def __init__(self, path: Path | str, *, database_url: str | None = None) -> None:
        from assistantx.store.postgres_store import PostgresStore, redact

        self.path = Path(path)
        self.where = str(self.path) if database_url is None else redact(database_url)
        self._db: SqliteStore  # or its PostgreSQL twin
        try:
            if database_url is not None:
                self._db = PostgresStore.open_url(database_url, EVENT_SCHEMA)
            else:
                # FULL: a commit is on disk before accept() returns, so an ack never loses
                # events.
                self._db = SqliteStore.open(self.path, EVENT_SCHEMA, synchronous="FULL")
        except SchemaError as exc:
            raise MessengerError(f"{self.where}: cannot open the event store: {exc}") from exc
        except database_errors() as exc:
            raise MessengerError(f"{self.where}: cannot open the event store: {exc}") from exc

    async def _run(self, work: Callable[[Connection], T]) -> T:
        try:
            return await self._db.acall(work)
        except StoreClosedError as exc:
            raise MessengerError(f"{self.where}: the event store is closed") from exc
        except database_errors() as exc:
            raise MessengerError(f"{self.where}: event store failed: {exc}") from exc

    async def transaction_seen(self, txn_id: str) -> bool:
        def work(db: Connection) -> bool:
            row = db.execute("SELECT 1 FROM transactions WHERE txn_id = ?", (txn_id,)).fetchone()
            return row is not None

        return await self._run(work)

    async def event_seen(self, platform: str, event_id: str) -> bool:
        def work(db: Connection) -> bool:
            row = db.execute(
                "SELECT 1 FROM inbound_events WHERE platform = ? AND event_id = ?",
                (platform, event_id),
            ).fetchone()
            return row is not None

        return await self._run(work)

    async def accept(
        self,
        messages: Sequence[InboundMessage],
        *,
        txn_id: str | None = None,
        sync_key: str | None = None,
        sync_token: str | None = None,
    ) -> list[InboundMessage]:
        if (sync_key is None) != (sync_token is None):
            raise ValueError("sync_key and sync_token go together")
        now = datetime.now(UTC).isoformat()

        rows = [(m, m.model_dump_json()) for m in messages]

        def work(db: Connection) -> list[InboundMessage]:
            fresh: list[InboundMessage] = []
            for message, body in rows:
                cursor = db.execute(
                    "INSERT INTO inbound_events (platform, event_id, message, accepted_at)"
                    " VALUES (?, ?, ?, ?) ON CONFLICT (platform, event_id) DO NOTHING",
                    (message.platform, message.event_id, body, now),
                )
                if cursor.rowcount == 1:
                    fresh.append(message)
            if txn_id is not None:
                db.execute(
                    "INSERT INTO transactions (txn_id, accepted_at) VALUES (?, ?)"
                    " ON CONFLICT (txn_id) DO NOTHING",
                    (txn_id, now),
                )
            if sync_key is not None:
                db.execute(
                    "INSERT INTO sync_tokens (sync_key, token, saved_at) VALUES (?, ?, ?)"
                    " ON CONFLICT (sync_key) DO UPDATE SET token=excluded.token,"
                    " saved_at=excluded.saved_at",
                    (sync_key, sync_token, now),
                )
            return fresh

        return await self._run(work)

    async def mark_handled(self, platform: str, event_id: str) -> None:
        def work(db: Connection) -> None:
            db.execute(
                "UPDATE inbound_events SET handled = 1 WHERE platform = ? AND event_id = ?",
                (platform, event_id),
            )

        await self._run(work)

    async def unhandled(self) -> list[InboundMessage]:
        def work(db: Connection) -> list[str]:
            rows = db.execute(
                "SELECT message FROM inbound_events WHERE handled = 0 ORDER BY seq"
            ).fetchall()
            return [str(row[0]) for row in rows]

        return [InboundMessage.model_validate_json(text) for text in await self._run(work)]

    async def sync_token(self, sync_key: str) -> str | None:
        def work(db: Connection) -> str | None:
            row = db.execute(
                "SELECT token FROM sync_tokens WHERE sync_key = ?", (sync_key,)
            ).fetchone()
            return None if row is None else str(row[0])

        return await self._run(work)

    async def claim(self, platform: str, event_ids: Sequence[str]) -> list[str]:
        now = datetime.now(UTC).isoformat()

        def work(db: Connection) -> list[str]:
            fresh: list[str] = []
            for event_id in event_ids:
                cursor = db.execute(
                    "INSERT INTO inbound_events"
                    " (platform, event_id, message, accepted_at, handled)"
                    " VALUES (?, ?, '{}', ?, 1) ON CONFLICT (platform, event_id) DO NOTHING",
                    (platform, event_id, now),
                )
                if cursor.rowcount == 1:
                    fresh.append(event_id)
            return fresh

        return await self._run(work)

    async def dm_rooms(self) -> dict[str, str]:
        def work(db: Connection) -> dict[str, str]:
            rows = db.execute("SELECT person, room_id FROM dm_rooms").fetchall()
            return {str(person): str(room) for person, room in rows}

        return await self._run(work)

    async def set_dm_room(self, person: str, room_id: str | None) -> None:
        now = datetime.now(UTC).isoformat()

        def work(db: Connection) -> None:
            if room_id is None:
                db.execute("DELETE FROM dm_rooms WHERE person = ?", (person,))
            else:
                db.execute(
                    "INSERT INTO dm_rooms (person, room_id, saved_at) VALUES (?, ?, ?)"
                    " ON CONFLICT (person) DO UPDATE SET room_id=excluded.room_id,"
                    " saved_at=excluded.saved_at",
                    (person, room_id, now),
                )

        await self._run(work)

    async def outbound_part(
        self, key: str, part: int, digest: str, *, room_id: str, instruction_id: str | None
    ) -> OutboundPart:
        now = datetime.now(UTC).isoformat()

        def work(db: Connection) -> OutboundPart:
            row = db.execute(
                "SELECT digest, room_id, closed, txn_id, event_id FROM outbound_parts"
                " WHERE key = ? AND part = ?",
                (key, part),
            ).fetchone()
            if row is not None and (row[0], row[1], row[2]) == (digest, room_id, 0):
                return OutboundPart(txn_id=str(row[3]), event_id=row[4])
            # New, or the key now names another message (a reused instruction id):
            # a fresh transaction id, so the homeserver cannot take it for a repeat.
            txn_id = f"ax{uuid.uuid4().hex}"
            db.execute(
                "INSERT INTO outbound_parts (key, part, digest, room_id,"
                " instruction_id, closed, txn_id, event_id, question_id, saved_at)"
                " VALUES (?, ?, ?, ?, ?, 0, ?, NULL, NULL, ?)"
                " ON CONFLICT (key, part) DO UPDATE SET digest=excluded.digest,"
                " room_id=excluded.room_id, instruction_id=excluded.instruction_id, closed=0,"
                " txn_id=excluded.txn_id, event_id=NULL, question_id=NULL,"
                " saved_at=excluded.saved_at",
                (key, part, digest, room_id, instruction_id, txn_id, now),
            )
            return OutboundPart(txn_id=txn_id, event_id=None)

        return await self._run(work)

    async def part_sent(self, txn_id: str, event_id: str, question_id: str | None) -> None:
        def work(db: Connection) -> None:
            db.execute(
                "UPDATE outbound_parts SET event_id = ?, question_id = ? WHERE txn_id = ?",
                (event_id, question_id or "", txn_id),
            )

        await self._run(work)

    async def close_instruction(self, instruction_id: str) -> None:
        def work(db: Connection) -> None:
            db.execute(
                "UPDATE outbound_parts SET closed = 1 WHERE instruction_id = ?", (instruction_id,)
            )

        await self._run(work)

    async def question_of(self, event_id: str) -> str | None:
        def work(db: Connection) -> str | None:
            row = db.execute(
                "SELECT question_id FROM outbound_parts WHERE event_id = ?", (event_id,)
            ).fetchone()
            return None if row is None else str(row[0] or "")

        return await self._run(work)

    async def remember_media(self, item: str, ref: str, name: str, mime: str) -> None:
        now = datetime.now(UTC).isoformat()

        def work(db: Connection) -> None:
            db.execute(
                "INSERT INTO media (item, ref, name, mime, saved_at) VALUES (?, ?, ?, ?, ?)"
                " ON CONFLICT (item) DO UPDATE SET ref=excluded.ref, name=excluded.name,"
                " mime=excluded.mime, saved_at=excluded.saved_at",
                (item, ref, name, mime, now),
            )

        await self._run(work)

    async def media(self, item: str) -> tuple[str, str, str] | None:
        def work(db: Connection) -> tuple[str, str, str] | None:
            row = db.execute("SELECT ref, name, mime FROM media WHERE item = ?", (item,)).fetchone()
            return None if row is None else (str(row[0]), str(row[1]), str(row[2]))

        return await self._run(work)

    async def close(self) -> None:
        """Commits what is queued, then closes; a second call does nothing."""
        await self._db.aclose()
