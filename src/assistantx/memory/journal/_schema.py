"""The journal's SQL schema; one version, created on first open.

Columns added since are listed in ``ADDED_COLUMNS`` and added to older files on open (their
default fills existing rows), so a journal written before keeps working.
"""

from __future__ import annotations

SCHEMA_VERSION = 1

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
