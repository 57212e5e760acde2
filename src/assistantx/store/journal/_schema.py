"""The journal's SQL schema, versioned by ``core.sqlite_store`` (store ``journal``).

Version 1 is the schema below. Journals written before the versions table existed count as
version 0: migration 1 creates what is missing, adds the columns listed in ``ADDED_COLUMNS``
(their default fills existing rows) and checks the version those files kept in ``meta``, so
a journal written before keeps working. A later change of the schema is a new migration.
"""

from __future__ import annotations

import sqlite3

from assistantx.core.errors import JournalError
from assistantx.store.sqlite_store import Schema, execute_script

SCHEMA_VERSION = 1  # also kept in meta('schema'), where versions before the helper kept it

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (
    key   TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS instructions (
    seq        INTEGER PRIMARY KEY AUTOINCREMENT,
    id         TEXT NOT NULL UNIQUE,
    requester  TEXT NOT NULL,
    text       TEXT NOT NULL,
    status     TEXT NOT NULL,
    outcome    TEXT,
    summary    TEXT,
    created_at REAL NOT NULL,
    updated_at REAL NOT NULL,
    cancel_requested INTEGER NOT NULL DEFAULT 0,
    stm        TEXT,
    steps      INTEGER NOT NULL DEFAULT 0,
    compacted  INTEGER NOT NULL DEFAULT 0
);
CREATE INDEX IF NOT EXISTS instructions_status ON instructions (status, seq);
CREATE INDEX IF NOT EXISTS instructions_requester ON instructions (requester, seq);
CREATE TABLE IF NOT EXISTS events (
    seq            INTEGER PRIMARY KEY AUTOINCREMENT,
    instruction_id TEXT NOT NULL,
    kind           TEXT NOT NULL,
    time           REAL NOT NULL,
    step           INTEGER,
    data           TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS events_instruction ON events (instruction_id, seq);
CREATE INDEX IF NOT EXISTS events_time ON events (time);
CREATE TABLE IF NOT EXISTS messages (
    seq             INTEGER PRIMARY KEY AUTOINCREMENT,
    direction       TEXT NOT NULL CHECK (direction IN ('in', 'out')),
    chat_kind       TEXT NOT NULL,
    chat_id         TEXT NOT NULL,
    sender          TEXT NOT NULL,
    text            TEXT NOT NULL,
    time            REAL NOT NULL,
    instruction_id  TEXT,
    question_id     TEXT,
    in_reply_to     TEXT,
    idempotency_key TEXT UNIQUE,
    event_id        TEXT UNIQUE,
    status          TEXT NOT NULL,
    message_id      TEXT,
    body            TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS messages_chat ON messages (chat_kind, chat_id, seq);
CREATE TABLE IF NOT EXISTS memory_updates (
    seq            INTEGER PRIMARY KEY AUTOINCREMENT,
    time           REAL NOT NULL,
    instruction_id TEXT,
    body           TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS state (
    name       TEXT PRIMARY KEY,
    updated_at REAL NOT NULL,
    body       TEXT NOT NULL
);
"""

# (table, column, definition) added after the first release of schema 1.
ADDED_COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("instructions", "steps", "INTEGER NOT NULL DEFAULT 0"),
    ("instructions", "compacted", "INTEGER NOT NULL DEFAULT 0"),  # trace dropped (retention)
)


def _version_1(db: sqlite3.Connection) -> None:
    execute_script(db, SCHEMA)
    for table, column, definition in ADDED_COLUMNS:
        present = {r[1] for r in db.execute(f"PRAGMA table_info({table})")}
        if column not in present:
            db.execute(f"ALTER TABLE {table} ADD COLUMN {column} {definition}")
    row = db.execute("SELECT value FROM meta WHERE key='schema'").fetchone()
    if row is None:
        db.execute("INSERT INTO meta VALUES ('schema', ?)", (str(SCHEMA_VERSION),))
    elif str(row[0]) != str(SCHEMA_VERSION):
        raise JournalError(f"journal schema {row[0]}, this version reads {SCHEMA_VERSION}")


JOURNAL_SCHEMA = Schema("journal", (_version_1,))
