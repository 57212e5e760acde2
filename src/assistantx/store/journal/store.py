"""The journal: an embedded SQLite database (WAL) that makes the service durable.

It holds instructions (with the latest short-term memory checkpoint), their trace events,
every message of the built-in messenger (outbound ones keyed by idempotency key, inbound ones
by platform event id), applied memory updates, and named state snapshots (the long-term
memory graph, the simulated world).

Durability: WAL with ``synchronous=NORMAL`` — a committed transaction survives a crash of the
process (``kill -9``); only an operating-system crash or power loss can lose the last
transactions. Writes go through the file's one writer thread (``core.sqlite_store``), which
commits whatever is queued as one group; they run in the order they were submitted, so the
journal's order is the order of the events they record. Code on the event loop awaits its
write (``arecord``, ``acheckpoint``, ``acreate_instruction``, ``arecord_outbound``, ``awrite``)
so the loop serves others meanwhile and the caller continues only once its write is
committed; the plain methods block their thread until committed (operator, start-up and CLI
writes). ``queue_states`` neither waits nor blocks (reads see it once committed): a record the
loop must make before anyone acts on an event, where acting journals too (ordered after it).
Reads use a second connection on the caller's thread; WAL lets them run beside the
writer, and they see every write whose call has returned.

On PostgreSQL the same holds: the writer is a ``PostgresStore`` (the same thread and group
commit on a psycopg connection), reads a second connection in autocommit mode, and a commit is
as durable as the server's settings make it. The statements are written once for both
(``store.connection``).
"""

from __future__ import annotations

import json
import logging
import sqlite3
import time
from collections.abc import Callable, Iterator
from concurrent.futures import Future
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal, TypeVar

from assistantx.core.errors import JournalError
from assistantx.core.events import TraceEvent
from assistantx.core.ports.messenger import ChatRef, InboundMessage, OutboundMessage
from assistantx.memory.short_term import ShortTermMemory
from assistantx.store.connection import (
    Connection,
    database_errors,
    integrity_errors,
    is_postgres_url,
)
from assistantx.store.journal._schema import JOURNAL_SCHEMA
from assistantx.store.leases import Lease, fence
from assistantx.store.sqlite_store import SchemaError, SqliteStore, connect

logger = logging.getLogger(__name__)

T = TypeVar("T")

Status = Literal["queued", "running", "done", "failed", "unachievable", "cancelled"]
FINAL_STATUSES: frozenset[str] = frozenset({"done", "failed", "unachievable", "cancelled"})
MAX_SEQ = 2**63 - 1
"""The largest sequence number SQLite stores (a signed 64-bit integer); larger ones a client
sends (``after``, ``Last-Event-ID``, cursors) are refused before they reach a query."""
STATUSES: tuple[Status, ...] = ("queued", "running", "done", "failed", "unachievable", "cancelled")


@dataclass(frozen=True)
class InstructionRecord:
    seq: int
    id: str
    requester: str
    text: str
    status: Status
    outcome: str | None
    summary: str | None
    created_at: float
    updated_at: float
    cancel_requested: bool
    stm: ShortTermMemory | None
    steps: int = 0  # steps begun, as of the last checkpoint (lists do not load the memory)


@dataclass(frozen=True)
class EventRecord:
    seq: int
    event: TraceEvent


@dataclass(frozen=True)
class MessageRecord:
    seq: int
    direction: Literal["in", "out"]
    chat: ChatRef
    sender: str
    text: str
    time: float
    instruction_id: str | None
    question_id: str | None
    in_reply_to: str | None
    status: str
    message_id: str | None
    body: dict[str, Any]


@dataclass(frozen=True)
class ChatSummary:
    chat: ChatRef
    messages: int
    last_time: float


class Journal:
    """One SQLite file or PostgreSQL database; open it with ``Journal.open(path)`` (or
    ``Journal.open(path, database_url=URL)``) and ``close()`` it at the end."""

    def __init__(self, writer: SqliteStore, reader: Connection) -> None:
        self.writer = writer  # every write, in one thread, committed in groups
        self._conn: Any = reader  # reads, on the caller's thread
        self.path = writer.path
        self.where = writer.where  # the file, or the database's URL without its password
        self._fence: Callable[[Connection], None] | None = None

    @classmethod
    def open(cls, path: Path, *, database_url: str | None = None) -> Journal:
        """The SQLite file at ``path``, or the PostgreSQL database at ``database_url``
        (``postgresql://...``) when one is given (``path`` is then unused)."""
        if database_url is not None:
            return cls._open_postgres(database_url)
        # synchronous=NORMAL: a commit survives kill -9; FULL would fsync every group.
        try:
            writer = SqliteStore.open(path, JOURNAL_SCHEMA, synchronous="NORMAL")
        except (JournalError, SchemaError) as exc:  # written by a newer version
            raise JournalError(f"{path}: {exc}") from exc
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{path}: not a usable journal ({exc})") from exc
        try:
            reader = connect(path, synchronous="NORMAL")
        except sqlite3.DatabaseError as exc:
            writer.close()
            raise JournalError(f"{path}: not a usable journal ({exc})") from exc
        return cls(writer, reader)

    @classmethod
    def _open_postgres(cls, url: str) -> Journal:
        from assistantx.store.postgres_store import PostgresStore, connect_postgres, redact

        where = redact(url)
        if not is_postgres_url(url):
            raise JournalError(f"{where}: a database URL starts with postgresql://")
        try:
            writer = PostgresStore.open_url(url, JOURNAL_SCHEMA)
        except SchemaError as exc:
            raise JournalError(f"{where}: {exc}") from exc
        except database_errors() as exc:
            raise JournalError(f"{where}: not a usable journal ({exc})") from exc
        try:
            reader = connect_postgres(url)
        except database_errors() as exc:
            writer.close()
            raise JournalError(f"{where}: not a usable journal ({exc})") from exc
        return cls(writer, reader)

    def close(self) -> None:
        """Commits what is queued, then closes; a second call does nothing."""
        self.writer.close()
        self._conn.close()

    def hold(self, lease: Lease | None) -> None:
        """Every write from now on runs under ``lease``: refused with LeaseLostError (and
        nothing of it written) once another holder took the office (``store.leases``);
        None writes without a lease again."""
        if lease is None:
            self._fence = None
        else:
            from assistantx.store.postgres_store import PostgresStore

            self._fence = fence(lease, postgres=isinstance(self.writer, PostgresStore))

    def _fenced(self, fn: Callable[[Connection], T]) -> Callable[[Connection], T]:
        check = self._fence
        if check is None:
            return fn

        def write(db: Connection) -> T:
            check(db)
            return fn(db)

        return write

    def write(self, fn: Callable[[Connection], T]) -> T:
        """Run ``fn`` in the writer's transaction and wait until it is committed."""
        return self.writer.call(self._fenced(fn))

    async def awrite(self, fn: Callable[[Connection], T]) -> T:
        """Like ``write``, but the event loop serves others while the group commits."""
        return await self.writer.acall(self._fenced(fn))

    @contextmanager
    def transaction(self) -> Iterator[Connection]:
        """Group reads of a consistent view (writes go through ``write``)."""
        self._conn.execute("BEGIN")
        try:
            yield self._conn
        finally:
            self._conn.execute("COMMIT")

    # -- instructions --------------------------------------------------------------------
    def create_instruction(
        self, instruction_id: str, requester: str, text: str, created_at: float
    ) -> InstructionRecord:
        seq = self.write(_insert_instruction(instruction_id, requester, text, created_at))
        return _queued(seq, instruction_id, requester, text, created_at)

    async def acreate_instruction(
        self,
        instruction_id: str,
        requester: str,
        text: str,
        created_at: float,
        *,
        notify: str | None = None,
    ) -> InstructionRecord:
        """The one insert of an admission; returns once it is committed. ``notify``: a
        PostgreSQL channel told the instruction's id in the same transaction (at commit)."""
        insert = _insert_instruction(instruction_id, requester, text, created_at)
        if notify is not None:
            channel = notify

            def insert_and_notify(db: Connection) -> int:
                seq = insert(db)
                db.execute("SELECT pg_notify(?, ?)", (channel, instruction_id))
                return seq

            seq = await self.awrite(insert_and_notify)
        else:
            seq = await self.awrite(insert)
        return _queued(seq, instruction_id, requester, text, created_at)

    def insert_instruction(self, stm: ShortTermMemory, status: Status = "running") -> None:
        """Insert a new instruction with its first checkpoint; JournalError when its id is
        taken (an instruction started without ``create_instruction``, e.g. from a message)."""
        self.write(_checkpoint(stm, status, insert_only=True))

    def checkpoint(self, stm: ShortTermMemory, status: Status = "running") -> None:
        """Store the instruction's latest memory in its own row (same id and requester);
        inserts the row when there is none, and never writes over another instruction's."""
        self.write(_checkpoint(stm, status))

    async def acheckpoint(self, stm: ShortTermMemory, status: Status = "running") -> None:
        await self.awrite(_checkpoint(stm, status))

    def record(
        self,
        event: TraceEvent,
        *,
        stm: ShortTermMemory | None = None,
        status: Status | None = None,
        states: dict[str, dict[str, Any]] | None = None,
        memory_updates: list[dict[str, Any]] | None = None,
    ) -> int:
        """One trace event with the checkpoint and state snapshots it implies, atomically."""
        return self.write(_record(event, stm, status, states, memory_updates))

    async def arecord(
        self,
        event: TraceEvent,
        *,
        stm: ShortTermMemory | None = None,
        status: Status | None = None,
        states: dict[str, dict[str, Any]] | None = None,
        memory_updates: list[dict[str, Any]] | None = None,
    ) -> int:
        """``record``, awaited: the caller continues once the group holding it committed."""
        return await self.awrite(_record(event, stm, status, states, memory_updates))

    def set_status(self, instruction_id: str, status: Status) -> None:
        self.write(_set_status(instruction_id, status, time.time()))

    async def aset_status(self, instruction_id: str, status: Status) -> None:
        """``set_status``, awaited: the event loop runs on while the writer commits."""
        await self.awrite(_set_status(instruction_id, status, time.time()))

    def request_cancel(self, instruction_id: str) -> None:
        self.write(_request_cancel(instruction_id, time.time()))

    async def arequest_cancel(self, instruction_id: str) -> None:
        await self.awrite(_request_cancel(instruction_id, time.time()))

    def instruction(self, instruction_id: str) -> InstructionRecord | None:
        row = self._conn.execute(
            "SELECT * FROM instructions WHERE id=?", (instruction_id,)
        ).fetchone()
        return _instruction(row) if row else None

    def instructions(
        self,
        *,
        status: Status | None = None,
        requester: str | None = None,
        after_seq: int = 0,
        limit: int = 50,
    ) -> list[InstructionRecord]:
        """Newest first; ``after_seq`` > 0 continues below that sequence number."""
        where: list[str] = ["1=1"]
        args: list[object] = []
        if status is not None:
            where.append("status=?")
            args.append(status)
        if requester is not None:
            where.append("requester=?")
            args.append(requester)
        if after_seq > 0:
            where.append("seq<?")
            args.append(after_seq)
        rows = self._conn.execute(
            "SELECT seq, id, requester, text, status, outcome, summary, created_at, updated_at,"
            f" cancel_requested, steps, NULL AS stm FROM instructions WHERE {' AND '.join(where)}"
            " ORDER BY seq DESC LIMIT ?",
            (*args, limit),
        ).fetchall()
        return [_instruction(r) for r in rows]

    def unfinished(self) -> list[InstructionRecord]:
        rows = self._conn.execute(
            "SELECT * FROM instructions WHERE status IN ('queued', 'running') ORDER BY seq"
        ).fetchall()
        return [_instruction(r) for r in rows]

    def count_by_status(self) -> dict[str, int]:
        rows = self._conn.execute("SELECT status, COUNT(*) FROM instructions GROUP BY status")
        return {str(r[0]): int(r[1]) for r in rows}

    # -- trace events --------------------------------------------------------------------
    def append_event(self, event: TraceEvent) -> int:
        return self.write(_record(event, None, None, None, None))

    def events(
        self, instruction_id: str | None = None, *, after_seq: int = 0, limit: int = 1000
    ) -> list[EventRecord]:
        match = {} if instruction_id is None else {"instruction_id": instruction_id}
        rows = self._page("events", match, after_seq, limit)
        return [
            EventRecord(
                seq=int(r["seq"]),
                event=TraceEvent(
                    instruction_id=r["instruction_id"],
                    kind=r["kind"],
                    time=r["time"],
                    step=r["step"],
                    data=json.loads(r["data"]),
                ),
            )
            for r in rows
        ]

    def last_event_seq(self) -> int:
        row = self._conn.execute("SELECT COALESCE(MAX(seq), 0) FROM events").fetchone()
        return int(row[0])

    def event_seq_before(self, time_s: float) -> int:
        """The sequence number after which the events at or after ``time_s`` begin."""
        row = self._conn.execute(
            "SELECT MIN(seq) FROM events WHERE time >= ?", (time_s,)
        ).fetchone()
        return self.last_event_seq() if row[0] is None else int(row[0]) - 1

    # -- retention -----------------------------------------------------------------------
    def compact(self, finished_before: float, *, batch: int = 200) -> int:
        """Drop the traces of instructions that ended before ``finished_before`` (epoch s).

        Their trace events and their short-term memory checkpoint go; the row with status,
        outcome, summary and step count stays, and so does every message (the audit lines of
        who was told what) and every memory update. Returns the instructions compacted."""
        done = 0
        while n := self.write(_compact(finished_before, batch)):
            done += n
        return done

    async def acompact(self, finished_before: float, *, batch: int = 200) -> int:
        """``compact`` in batches of one group commit each: other writers wait one batch."""
        done = 0
        while n := await self.awrite(_compact(finished_before, batch)):
            done += n
        return done

    # -- messages ------------------------------------------------------------------------
    def record_outbound(self, message: OutboundMessage, sender: str, now: float) -> MessageRecord:
        """Journal an outbound message before it is sent; an existing key returns its record."""
        return self.write(_insert_outbound(message, sender, now))

    async def arecord_outbound(
        self, message: OutboundMessage, sender: str, now: float
    ) -> MessageRecord:
        return await self.awrite(_insert_outbound(message, sender, now))

    def mark_sent(self, seq: int, message_id: str) -> None:
        self.write(_mark_sent(seq, message_id))

    async def amark_sent(self, seq: int, message_id: str) -> None:
        await self.awrite(_mark_sent(seq, message_id))

    def outbound(self, idempotency_key: str) -> MessageRecord | None:
        row = self._conn.execute(
            "SELECT * FROM messages WHERE idempotency_key=?", (idempotency_key,)
        ).fetchone()
        return _message(row) if row else None

    def record_inbound(self, message: InboundMessage) -> MessageRecord | None:
        """Journal an inbound message; None when its event id was seen before (a duplicate)."""
        return self.write(_record_inbound(message))

    async def arecord_inbound(self, message: InboundMessage) -> MessageRecord | None:
        """``record_inbound``, awaited: the event loop runs on while the writer commits."""
        return await self.awrite(_record_inbound(message))

    def messages_of(self, instruction_id: str) -> list[MessageRecord]:
        """The outbound messages of one instruction and the inbound replies to its questions."""
        rows = self._conn.execute(
            "SELECT * FROM messages WHERE instruction_id=? OR in_reply_to LIKE ? ORDER BY seq",
            (instruction_id, instruction_id + ":%"),
        ).fetchall()
        return [_message(r) for r in rows]

    def messages(
        self, chat: ChatRef | None = None, *, after_seq: int = 0, limit: int = 200
    ) -> list[MessageRecord]:
        match = {} if chat is None else {"chat_kind": chat.kind, "chat_id": chat.id}
        return [_message(r) for r in self._page("messages", match, after_seq, limit)]

    def _page(
        self, table: str, match: dict[str, str], after_seq: int, limit: int
    ) -> list[sqlite3.Row]:
        """The rows of ``table`` after ``after_seq`` whose columns equal ``match``, oldest
        first, at most ``limit``: how a reader pages through the events or the messages."""
        where = " AND ".join([*(f"{column}=?" for column in match), "seq>?"])
        rows: list[sqlite3.Row] = self._conn.execute(
            f"SELECT * FROM {table} WHERE {where} ORDER BY seq LIMIT ?",
            (*match.values(), after_seq, limit),
        ).fetchall()
        return rows

    def chats(self) -> list[ChatSummary]:
        rows = self._conn.execute(
            "SELECT chat_kind, chat_id, COUNT(*) AS n, MAX(time) AS last FROM messages"
            " GROUP BY chat_kind, chat_id ORDER BY last DESC"
        ).fetchall()
        return [
            ChatSummary(
                chat=ChatRef(kind=r["chat_kind"], id=r["chat_id"]),
                messages=int(r["n"]),
                last_time=float(r["last"]),
            )
            for r in rows
        ]

    # -- memory and named state ----------------------------------------------------------
    def record_memory_update(
        self, time_s: float, instruction_id: str | None, body: dict[str, Any]
    ) -> None:
        text = json.dumps(body)
        self.write(lambda db: _insert_memory_update(db, time_s, instruction_id, text))

    async def arecord_memory_update(
        self, time_s: float, instruction_id: str | None, body: dict[str, Any]
    ) -> None:
        text = json.dumps(body)
        await self.awrite(lambda db: _insert_memory_update(db, time_s, instruction_id, text))

    def memory_updates(self, limit: int = 1000) -> list[dict[str, Any]]:
        rows = self._conn.execute(
            "SELECT body FROM memory_updates ORDER BY seq DESC LIMIT ?", (limit,)
        ).fetchall()
        return [json.loads(r["body"]) for r in reversed(rows)]

    def memory_updates_after(self, seq: int) -> list[dict[str, Any]]:
        """The updates journaled after ``seq`` (those a snapshot through ``seq`` lacks)."""
        rows = self._conn.execute(
            "SELECT body FROM memory_updates WHERE seq>? ORDER BY seq", (seq,)
        ).fetchall()
        return [json.loads(r["body"]) for r in rows]

    def put_state(self, name: str, body: dict[str, Any]) -> None:
        text = json.dumps(body)
        self.write(lambda db: _put_state(db, name, text))

    def put_states(self, states: dict[str, dict[str, Any]]) -> None:
        """Several state rows in one transaction (all of them or none survive a crash)."""
        rows = [(name, json.dumps(body)) for name, body in states.items()]
        self.write(_put_states(rows))

    def queue_states(self, states: dict[str, dict[str, Any]]) -> Future[None]:
        """``put_states`` queued behind every write submitted before it and ahead of every
        write after it, without waiting for its commit: a crash before that commit loses every
        later write too, so the journal never holds what came after without it. The future
        says whether it was committed (the caller logs a failure)."""
        rows = [(name, json.dumps(body)) for name, body in states.items()]
        return self.writer.submit(self._fenced(_put_states(rows)))

    async def aput_states(self, states: dict[str, dict[str, Any]]) -> None:
        rows = [(name, json.dumps(body)) for name, body in states.items()]
        await self.awrite(_put_states(rows))

    def put_memory_snapshot(self, name: str, body: dict[str, Any]) -> None:
        """A snapshot stamped with the last memory update journaled before it (``through``)."""
        self.write(_put_memory_snapshot(name, body))

    async def aput_memory_snapshot(self, name: str, body: dict[str, Any]) -> None:
        await self.awrite(_put_memory_snapshot(name, body))

    def state(self, name: str) -> dict[str, Any] | None:
        row = self._conn.execute("SELECT body FROM state WHERE name=?", (name,)).fetchone()
        if row is None:
            return None
        body: dict[str, Any] = json.loads(row["body"])
        return body


@contextmanager
def _new_id(instruction_id: str) -> Iterator[None]:
    """Turns the primary key's refusal of a taken id into a clear error."""
    try:
        yield
    except integrity_errors() as exc:
        raise JournalError(f"instruction id {instruction_id!r} is taken") from exc


# -- writes: each builds its arguments on the caller's thread, then runs in the writer's -----
def _insert_instruction(
    instruction_id: str, requester: str, text: str, created_at: float
) -> Callable[[Connection], int]:
    def insert(db: Connection) -> int:
        with _new_id(instruction_id):
            cur = db.execute(
                "INSERT INTO instructions (id, requester, text, status, created_at, updated_at)"
                " VALUES (?, ?, ?, 'queued', ?, ?) RETURNING seq",
                (instruction_id, requester, text, created_at, created_at),
            )
            return int(cur.fetchone()[0])

    return insert


def _queued(
    seq: int, instruction_id: str, requester: str, text: str, created_at: float
) -> InstructionRecord:
    return InstructionRecord(
        seq=seq,
        id=instruction_id,
        requester=requester,
        text=text,
        status="queued",
        outcome=None,
        summary=None,
        created_at=created_at,
        updated_at=created_at,
        cancel_requested=False,
        stm=None,
    )


def _checkpoint(
    stm: ShortTermMemory, status: Status, *, insert_only: bool = False
) -> Callable[[Connection], None]:
    """Update the instruction's own row (same id and requester), else insert it; an id taken
    by another instruction raises JournalError, never overwrites (``insert_only``: always a
    new row)."""
    # Serialised now, on the loop: the memory goes on changing once the caller continues.
    now = time.time()
    body = stm.model_dump_json()
    trace = stm.trace
    update = (
        status,
        trace.outcome,
        trace.summary,
        now,
        body,
        len(trace.steps),
        stm.instruction_id,
        stm.requester,
    )
    insert = (
        stm.instruction_id,
        stm.requester,
        stm.text,
        status,
        trace.outcome,
        trace.summary,
        trace.started_at,
        now,
        body,
        len(trace.steps),
    )

    def write(db: Connection) -> None:
        if not insert_only:
            cur = db.execute(
                "UPDATE instructions SET status=?, outcome=?, summary=?, updated_at=?, stm=?,"
                " steps=? WHERE id=? AND requester=?",
                update,
            )
            if cur.rowcount:
                return
        with _new_id(stm.instruction_id):
            db.execute(
                "INSERT INTO instructions (id, requester, text, status, outcome, summary,"
                " created_at, updated_at, stm, steps) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                insert,
            )

    return write


def _record(
    event: TraceEvent,
    stm: ShortTermMemory | None,
    status: Status | None,
    states: dict[str, dict[str, Any]] | None,
    memory_updates: list[dict[str, Any]] | None,
) -> Callable[[Connection], int]:
    row = (event.instruction_id, event.kind, event.time, event.step, json.dumps(event.data))
    checkpoint = _checkpoint(stm, status or "running") if stm is not None else None
    now = time.time()
    state_rows = [(name, json.dumps(body)) for name, body in (states or {}).items()]
    updates = [json.dumps(u) for u in memory_updates or ()]

    def write(db: Connection) -> int:
        seq = int(
            db.execute(
                "INSERT INTO events (instruction_id, kind, time, step, data)"
                " VALUES (?, ?, ?, ?, ?) RETURNING seq",
                row,
            ).fetchone()[0]
        )
        if checkpoint is not None:
            checkpoint(db)
        elif status is not None:
            db.execute(
                "UPDATE instructions SET status=?, updated_at=? WHERE id=?",
                (status, now, event.instruction_id),
            )
        for body in updates:
            _insert_memory_update(db, event.time, event.instruction_id, body)
        for name, text in state_rows:
            _put_state(db, name, text)
        return seq

    return write


def _compact(finished_before: float, batch: int) -> Callable[[Connection], int]:
    def write(db: Connection) -> int:
        ids = [
            str(r[0])
            for r in db.execute(
                "SELECT id FROM instructions WHERE compacted = 0 AND updated_at < ? AND status IN"
                " ('done', 'failed', 'unachievable', 'cancelled') LIMIT ?",
                (finished_before, batch),
            )
        ]
        if ids:
            marks = ",".join("?" * len(ids))
            db.execute(f"DELETE FROM events WHERE instruction_id IN ({marks})", ids)
            db.execute(f"UPDATE instructions SET stm=NULL, compacted=1 WHERE id IN ({marks})", ids)
        return len(ids)

    return write


def _insert_memory_update(
    db: Connection, time_s: float, instruction_id: str | None, body: str
) -> None:
    db.execute(
        "INSERT INTO memory_updates (time, instruction_id, body) VALUES (?, ?, ?)",
        (time_s, instruction_id, body),
    )


def _put_memory_snapshot(name: str, body: dict[str, Any]) -> Callable[[Connection], None]:
    """``body`` must be a fresh structure nobody changes: it is encoded on the writer thread."""

    def write(db: Connection) -> None:
        # Writes are ordered, so every update applied before the snapshot is journaled by now.
        through = db.execute("SELECT COALESCE(MAX(seq), 0) FROM memory_updates").fetchone()[0]
        _put_state(db, name, json.dumps({**body, "through": int(through)}))

    return write


def _put_states(rows: list[tuple[str, str]]) -> Callable[[Connection], None]:
    def write(db: Connection) -> None:
        for name, text in rows:
            _put_state(db, name, text)

    return write


def _put_state(db: Connection, name: str, text: str) -> None:
    db.execute(
        "INSERT INTO state (name, updated_at, body) VALUES (?, ?, ?)"
        " ON CONFLICT(name) DO UPDATE SET updated_at=excluded.updated_at, body=excluded.body",
        (name, time.time(), text),
    )


def _insert_outbound(
    message: OutboundMessage, sender: str, now: float
) -> Callable[[Connection], MessageRecord]:
    key = message.idempotency_key
    args = (
        message.chat.kind,
        message.chat.id,
        sender,
        message.text,
        now,
        message.instruction_id,
        message.question_id,
        key,
        json.dumps(message.model_dump(mode="json")),
    )

    def insert(db: Connection) -> MessageRecord:
        if key is not None:
            row = db.execute("SELECT * FROM messages WHERE idempotency_key=?", (key,)).fetchone()
            if row is not None:
                return _message(row)
        cur = db.execute(
            "INSERT INTO messages (direction, chat_kind, chat_id, sender, text, time,"
            " instruction_id, question_id, idempotency_key, status, body)"
            " VALUES ('out', ?, ?, ?, ?, ?, ?, ?, ?, 'pending', ?) RETURNING seq",
            args,
        )
        record = _message_by_seq(db, int(cur.fetchone()[0]))
        assert record is not None
        return record

    return insert


def _mark_sent(seq: int, message_id: str) -> Callable[[Connection], None]:
    def write(db: Connection) -> None:
        db.execute("UPDATE messages SET status='sent', message_id=? WHERE seq=?", (message_id, seq))

    return write


def _message_by_seq(db: Connection, seq: int) -> MessageRecord | None:
    row = db.execute("SELECT * FROM messages WHERE seq=?", (seq,)).fetchone()
    return _message(row) if row else None


def _instruction(row: Any) -> InstructionRecord:
    stm = row["stm"]
    return InstructionRecord(
        seq=int(row["seq"]),
        id=row["id"],
        requester=row["requester"],
        text=row["text"],
        status=row["status"],
        outcome=row["outcome"],
        summary=row["summary"],
        created_at=float(row["created_at"]),
        updated_at=float(row["updated_at"]),
        cancel_requested=bool(row["cancel_requested"]),
        stm=ShortTermMemory.model_validate_json(stm) if stm else None,
        steps=int(row["steps"]),
    )


def _message(row: Any) -> MessageRecord:
    return MessageRecord(
        seq=int(row["seq"]),
        direction=row["direction"],
        chat=ChatRef(kind=row["chat_kind"], id=row["chat_id"]),
        sender=row["sender"],
        text=row["text"],
        time=float(row["time"]),
        instruction_id=row["instruction_id"],
        question_id=row["question_id"],
        in_reply_to=row["in_reply_to"],
        status=row["status"],
        message_id=row["message_id"],
        body=json.loads(row["body"]),
    )


def _record_inbound(
    message: InboundMessage,
) -> Callable[[Connection], MessageRecord | None]:
    event_id = f"{message.platform}:{message.event_id}"
    args = (
        message.chat.kind,
        message.chat.id,
        message.sender,
        message.text,
        message.time.timestamp(),
        message.in_reply_to,
        event_id,
        message.model_dump_json(),
    )

    def insert(db: Connection) -> MessageRecord | None:
        # ON CONFLICT, not a caught IntegrityError: on PostgreSQL a failed statement aborts
        # the whole transaction (the group's other writes with it).
        row = db.execute(
            "INSERT INTO messages (direction, chat_kind, chat_id, sender, text, time,"
            " in_reply_to, event_id, status, body)"
            " VALUES ('in', ?, ?, ?, ?, ?, ?, ?, 'received', ?)"
            " ON CONFLICT (event_id) DO NOTHING RETURNING seq",
            args,
        ).fetchone()
        return None if row is None else _message_by_seq(db, int(row[0]))

    return insert


def _set_status(instruction_id: str, status: Status, now: float) -> Callable[[Connection], Any]:
    return lambda db: db.execute(
        "UPDATE instructions SET status=?, updated_at=? WHERE id=?", (status, now, instruction_id)
    )


def _request_cancel(instruction_id: str, now: float) -> Callable[[Connection], Any]:
    return lambda db: db.execute(
        "UPDATE instructions SET cancel_requested=1, updated_at=? WHERE id=?", (now, instruction_id)
    )
