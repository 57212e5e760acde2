"""The journal: an embedded SQLite database (WAL) that makes the service durable.

It holds instructions (with the latest short-term memory checkpoint), their trace events,
every message of the built-in messenger (outbound ones keyed by idempotency key, inbound ones
by platform event id), applied memory updates, and named state snapshots (the long-term
memory graph, the simulated world).

Durability: WAL with ``synchronous=NORMAL`` — a committed transaction survives a crash of the
process (``kill -9``); only an operating-system crash or power loss can lose the last
transactions. Writes are small and run on the event loop thread (one connection), so their
order is the order of the events they record.
"""

from __future__ import annotations

import json
import logging
import sqlite3
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from assistantx.adapters.messenger.base import ChatRef, InboundMessage, OutboundMessage
from assistantx.errors import JournalError
from assistantx.journal._schema import ADDED_COLUMNS, SCHEMA, SCHEMA_VERSION
from assistantx.memory.short_term import ShortTermMemory
from assistantx.ppdr.events import TraceEvent

logger = logging.getLogger(__name__)

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
    """One SQLite file; open it with ``Journal.open(path)`` and ``close()`` it at the end."""

    def __init__(self, conn: sqlite3.Connection, path: Path) -> None:
        self._conn = conn
        self.path = path

    @classmethod
    def open(cls, path: Path) -> Journal:
        path.parent.mkdir(parents=True, exist_ok=True)
        conn = sqlite3.connect(path, isolation_level=None, check_same_thread=False)
        conn.row_factory = sqlite3.Row
        try:
            conn.execute("PRAGMA journal_mode=WAL")
            conn.execute("PRAGMA synchronous=NORMAL")
            conn.execute("PRAGMA busy_timeout=5000")
            conn.executescript(SCHEMA)
            _add_missing_columns(conn)
            row = conn.execute("SELECT value FROM meta WHERE key='schema'").fetchone()
            if row is None:
                conn.execute("INSERT INTO meta VALUES ('schema', ?)", (str(SCHEMA_VERSION),))
        except sqlite3.DatabaseError as exc:
            conn.close()
            raise JournalError(f"{path}: not a usable journal ({exc})") from exc
        if row is not None and int(row["value"]) != SCHEMA_VERSION:
            conn.close()
            raise JournalError(
                f"{path}: journal schema {row['value']}, this version reads {SCHEMA_VERSION}"
            )
        return cls(conn, path)

    def close(self) -> None:
        self._conn.close()

    @contextmanager
    def transaction(self) -> Iterator[sqlite3.Connection]:
        """Group writes so they commit together (or not at all)."""
        self._conn.execute("BEGIN IMMEDIATE")
        try:
            yield self._conn
        except BaseException:
            self._conn.execute("ROLLBACK")
            raise
        self._conn.execute("COMMIT")

    # -- instructions --------------------------------------------------------------------
    def create_instruction(
        self, instruction_id: str, requester: str, text: str, created_at: float
    ) -> InstructionRecord:
        """Insert a new instruction; JournalError when its id is taken (never overwrites)."""
        with self.transaction() as db, _new_id(instruction_id):
            db.execute(
                "INSERT INTO instructions (id, requester, text, status, created_at, updated_at)"
                " VALUES (?, ?, ?, 'queued', ?, ?)",
                (instruction_id, requester, text, created_at, created_at),
            )
        record = self.instruction(instruction_id)
        assert record is not None
        return record

    def insert_instruction(self, stm: ShortTermMemory, status: Status = "running") -> None:
        """Insert a new instruction with its first checkpoint; JournalError when its id is
        taken (an instruction started without ``create_instruction``, e.g. from a message)."""
        with self.transaction() as db, _new_id(stm.instruction_id):
            self._insert(db, stm, status)

    def checkpoint(self, stm: ShortTermMemory, status: Status = "running") -> None:
        """Store the instruction's latest memory in its own row (same id and requester);
        inserts the row when there is none, and never writes over another instruction's."""
        with self.transaction() as db:
            self._checkpoint(db, stm, status)

    def record(
        self,
        event: TraceEvent,
        *,
        stm: ShortTermMemory | None = None,
        status: Status | None = None,
        states: dict[str, dict[str, Any]] | None = None,
    ) -> int:
        """One trace event with the checkpoint and state snapshots it implies, atomically."""
        with self.transaction() as db:
            seq = self._append_event(db, event)
            if stm is not None:
                self._checkpoint(db, stm, status or "running")
            elif status is not None:
                db.execute(
                    "UPDATE instructions SET status=?, updated_at=? WHERE id=?",
                    (status, time.time(), event.instruction_id),
                )
            for name, body in (states or {}).items():
                self._put_state(db, name, body)
        return seq

    def _checkpoint(self, db: sqlite3.Connection, stm: ShortTermMemory, status: Status) -> None:
        now = time.time()
        body = stm.model_dump_json()
        trace = stm.trace
        cur = db.execute(
            "UPDATE instructions SET status=?, outcome=?, summary=?, updated_at=?, stm=?,"
            " steps=? WHERE id=? AND requester=?",
            (
                status,
                trace.outcome,
                trace.summary,
                now,
                body,
                len(trace.steps),
                stm.instruction_id,
                stm.requester,
            ),
        )
        if cur.rowcount == 0:
            with _new_id(stm.instruction_id):  # a row of another requester: an error
                self._insert(db, stm, status)

    def _insert(self, db: sqlite3.Connection, stm: ShortTermMemory, status: Status) -> None:
        now = time.time()
        trace = stm.trace
        db.execute(
            "INSERT INTO instructions (id, requester, text, status, outcome, summary,"
            " created_at, updated_at, stm, steps) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
            (
                stm.instruction_id,
                stm.requester,
                stm.text,
                status,
                trace.outcome,
                trace.summary,
                trace.started_at,
                now,
                stm.model_dump_json(),
                len(trace.steps),
            ),
        )

    def set_status(self, instruction_id: str, status: Status) -> None:
        self._conn.execute(
            "UPDATE instructions SET status=?, updated_at=? WHERE id=?",
            (status, time.time(), instruction_id),
        )

    def request_cancel(self, instruction_id: str) -> None:
        self._conn.execute(
            "UPDATE instructions SET cancel_requested=1, updated_at=? WHERE id=?",
            (time.time(), instruction_id),
        )

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
        return self._append_event(self._conn, event)

    def _append_event(self, db: sqlite3.Connection, event: TraceEvent) -> int:
        cur = db.execute(
            "INSERT INTO events (instruction_id, kind, time, step, data) VALUES (?, ?, ?, ?, ?)",
            (event.instruction_id, event.kind, event.time, event.step, json.dumps(event.data)),
        )
        return int(cur.lastrowid or 0)

    def events(
        self, instruction_id: str | None = None, *, after_seq: int = 0, limit: int = 1000
    ) -> list[EventRecord]:
        if instruction_id is None:
            rows = self._conn.execute(
                "SELECT * FROM events WHERE seq>? ORDER BY seq LIMIT ?", (after_seq, limit)
            ).fetchall()
        else:
            rows = self._conn.execute(
                "SELECT * FROM events WHERE instruction_id=? AND seq>? ORDER BY seq LIMIT ?",
                (instruction_id, after_seq, limit),
            ).fetchall()
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

    # -- messages ------------------------------------------------------------------------
    def record_outbound(self, message: OutboundMessage, sender: str, now: float) -> MessageRecord:
        """Journal an outbound message before it is sent; an existing key returns its record."""
        key = message.idempotency_key
        if key is not None:
            existing = self.outbound(key)
            if existing is not None:
                return existing
        body = message.model_dump(mode="json")
        cur = self._conn.execute(
            "INSERT INTO messages (direction, chat_kind, chat_id, sender, text, time,"
            " instruction_id, question_id, idempotency_key, status, body)"
            " VALUES ('out', ?, ?, ?, ?, ?, ?, ?, ?, 'pending', ?)",
            (
                message.chat.kind,
                message.chat.id,
                sender,
                message.text,
                now,
                message.instruction_id,
                message.question_id,
                key,
                json.dumps(body),
            ),
        )
        record = self._message_by_seq(int(cur.lastrowid or 0))
        assert record is not None
        return record

    def mark_sent(self, seq: int, message_id: str) -> None:
        self._conn.execute(
            "UPDATE messages SET status='sent', message_id=? WHERE seq=?", (message_id, seq)
        )

    def outbound(self, idempotency_key: str) -> MessageRecord | None:
        row = self._conn.execute(
            "SELECT * FROM messages WHERE idempotency_key=?", (idempotency_key,)
        ).fetchone()
        return _message(row) if row else None

    def record_inbound(self, message: InboundMessage) -> MessageRecord | None:
        """Journal an inbound message; None when its event id was seen before (a duplicate)."""
        event_id = f"{message.platform}:{message.event_id}"
        try:
            cur = self._conn.execute(
                "INSERT INTO messages (direction, chat_kind, chat_id, sender, text, time,"
                " in_reply_to, event_id, status, body)"
                " VALUES ('in', ?, ?, ?, ?, ?, ?, ?, 'received', ?)",
                (
                    message.chat.kind,
                    message.chat.id,
                    message.sender,
                    message.text,
                    message.time.timestamp(),
                    message.in_reply_to,
                    event_id,
                    message.model_dump_json(),
                ),
            )
        except sqlite3.IntegrityError:
            return None
        return self._message_by_seq(int(cur.lastrowid or 0))

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
        if chat is None:
            rows = self._conn.execute(
                "SELECT * FROM messages WHERE seq>? ORDER BY seq LIMIT ?", (after_seq, limit)
            ).fetchall()
        else:
            rows = self._conn.execute(
                "SELECT * FROM messages WHERE chat_kind=? AND chat_id=? AND seq>?"
                " ORDER BY seq LIMIT ?",
                (chat.kind, chat.id, after_seq, limit),
            ).fetchall()
        return [_message(r) for r in rows]

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

    def _message_by_seq(self, seq: int) -> MessageRecord | None:
        row = self._conn.execute("SELECT * FROM messages WHERE seq=?", (seq,)).fetchone()
        return _message(row) if row else None

    # -- memory and named state ----------------------------------------------------------
    def record_memory_update(
        self, time_s: float, instruction_id: str | None, body: dict[str, Any]
    ) -> None:
        self._conn.execute(
            "INSERT INTO memory_updates (time, instruction_id, body) VALUES (?, ?, ?)",
            (time_s, instruction_id, json.dumps(body)),
        )

    def memory_updates(self, limit: int = 1000) -> list[dict[str, Any]]:
        rows = self._conn.execute(
            "SELECT body FROM memory_updates ORDER BY seq DESC LIMIT ?", (limit,)
        ).fetchall()
        return [json.loads(r["body"]) for r in reversed(rows)]

    def put_state(self, name: str, body: dict[str, Any]) -> None:
        self._put_state(self._conn, name, body)

    def _put_state(self, db: sqlite3.Connection, name: str, body: dict[str, Any]) -> None:
        db.execute(
            "INSERT INTO state (name, updated_at, body) VALUES (?, ?, ?)"
            " ON CONFLICT(name) DO UPDATE SET updated_at=excluded.updated_at, body=excluded.body",
            (name, time.time(), json.dumps(body)),
        )

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
    except sqlite3.IntegrityError as exc:
        raise JournalError(f"instruction id {instruction_id!r} is taken") from exc


def _instruction(row: sqlite3.Row) -> InstructionRecord:
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


def _add_missing_columns(conn: sqlite3.Connection) -> None:
    for table, column, definition in ADDED_COLUMNS:
        present = {r[1] for r in conn.execute(f"PRAGMA table_info({table})")}
        if column not in present:
            conn.execute(f"ALTER TABLE {table} ADD COLUMN {column} {definition}")


def _message(row: sqlite3.Row) -> MessageRecord:
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
