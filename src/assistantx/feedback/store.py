"""Survey answers, opt-outs and per-instruction impact, kept in the service's SQLite journal.

The tables (prefixed ``feedback_``) live in the journal's file next to its own tables, so an
instruction, its survey and its walking figures are backed up and restored together. This
module opens its own connection (WAL lets several connections share the file) and creates its
tables when missing; it never touches the journal's tables.

Every reply a person sends to a survey is stored verbatim with what it did, so a reply that
could not be read is never lost.
"""

from __future__ import annotations

import sqlite3
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from assistantx.core.errors import JournalError
from assistantx.feedback.impact import InstructionRecord
from assistantx.feedback.survey import Survey, SurveyState

_SCHEMA = """
CREATE TABLE IF NOT EXISTS feedback_instruction (
    instruction_id TEXT PRIMARY KEY,
    requester      TEXT NOT NULL,
    ended_at       REAL NOT NULL,
    body           TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS feedback_instruction_ended ON feedback_instruction (ended_at);
CREATE TABLE IF NOT EXISTS feedback_survey (
    instruction_id TEXT PRIMARY KEY,
    person         TEXT NOT NULL,
    state          TEXT NOT NULL,
    sent_at        REAL NOT NULL,
    body           TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS feedback_survey_person ON feedback_survey (person, state, sent_at);
CREATE TABLE IF NOT EXISTS feedback_reply (
    seq            INTEGER PRIMARY KEY AUTOINCREMENT,
    instruction_id TEXT NOT NULL,
    person         TEXT NOT NULL,
    time           REAL NOT NULL,
    text           TEXT NOT NULL,
    effect         TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS feedback_optout (
    person TEXT PRIMARY KEY,
    since  REAL NOT NULL
);
"""
ACTIVE_STATES = (SurveyState.OPEN.value, SurveyState.COMPLETE.value)


class FeedbackStore:
    """``FeedbackStore.open(path)`` on the journal file (or any SQLite file); ``close()`` it."""

    def __init__(self, conn: sqlite3.Connection, path: Path) -> None:
        self._conn = conn
        self._lock = threading.Lock()  # the report may be read from a worker thread
        self.path = path

    @classmethod
    def open(cls, path: Path) -> FeedbackStore:
        path.parent.mkdir(parents=True, exist_ok=True)
        conn = sqlite3.connect(path, isolation_level=None, check_same_thread=False)
        try:
            conn.execute("PRAGMA journal_mode=WAL")
            # As durable as the journal's own tables (a kill -9 loses nothing committed); FULL
            # would fsync on every commit, and a reminder tick commits once per survey.
            conn.execute("PRAGMA synchronous=NORMAL")
            conn.execute("PRAGMA busy_timeout=5000")
            conn.executescript(_SCHEMA)
        except sqlite3.DatabaseError as exc:
            conn.close()
            raise JournalError(f"{path}: cannot hold survey data ({exc})") from exc
        return cls(conn, path)

    def close(self) -> None:
        with self._lock:
            self._conn.close()

    @contextmanager
    def _write(self) -> Iterator[sqlite3.Connection]:
        with self._lock:
            self._conn.execute("BEGIN IMMEDIATE")
            try:
                yield self._conn
            except BaseException:
                self._conn.execute("ROLLBACK")
                raise
            self._conn.execute("COMMIT")

    # -- instructions --------------------------------------------------------------------
    def put_instruction(self, record: InstructionRecord) -> None:
        with self._write() as db:
            db.execute(
                "INSERT OR REPLACE INTO feedback_instruction VALUES (?, ?, ?, ?)",
                (
                    record.instruction_id,
                    record.requester,
                    record.ended_at,
                    record.model_dump_json(),
                ),
            )

    def instruction(self, instruction_id: str) -> InstructionRecord | None:
        with self._lock:
            row = self._conn.execute(
                "SELECT body FROM feedback_instruction WHERE instruction_id=?", (instruction_id,)
            ).fetchone()
        return InstructionRecord.model_validate_json(row[0]) if row else None

    def instructions(
        self, start: float | None = None, end: float | None = None
    ) -> list[InstructionRecord]:
        """Instructions that ended in [start, end), oldest first."""
        lo = float("-inf") if start is None else start
        hi = float("inf") if end is None else end
        with self._lock:
            rows = self._conn.execute(
                "SELECT body FROM feedback_instruction WHERE ended_at >= ? AND ended_at < ?"
                " ORDER BY ended_at, instruction_id",
                (lo, hi),
            ).fetchall()
        return [InstructionRecord.model_validate_json(r[0]) for r in rows]

    # -- surveys -------------------------------------------------------------------------
    def put_survey(self, survey: Survey) -> None:
        with self._write() as db:
            self._put_survey(db, survey)

    def _put_survey(self, db: sqlite3.Connection, survey: Survey) -> None:
        db.execute(
            "INSERT OR REPLACE INTO feedback_survey VALUES (?, ?, ?, ?, ?)",
            (
                survey.instruction_id,
                survey.person,
                survey.state.value,
                survey.sent_at,
                survey.model_dump_json(),
            ),
        )

    def survey(self, instruction_id: str) -> Survey | None:
        with self._lock:
            row = self._conn.execute(
                "SELECT body FROM feedback_survey WHERE instruction_id=?", (instruction_id,)
            ).fetchone()
        return Survey.model_validate_json(row[0]) if row else None

    def surveys(self, instruction_ids: list[str] | None = None) -> list[Survey]:
        with self._lock:
            rows = self._conn.execute(
                "SELECT body FROM feedback_survey ORDER BY sent_at, instruction_id"
            ).fetchall()
        surveys = [Survey.model_validate_json(r[0]) for r in rows]
        if instruction_ids is None:
            return surveys
        wanted = set(instruction_ids)
        return [s for s in surveys if s.instruction_id in wanted]

    def active_surveys(self, person: str | None = None) -> list[Survey]:
        """Surveys that may still take replies (open, or complete awaiting a comment)."""
        query = "SELECT body FROM feedback_survey WHERE state IN (?, ?)"
        args: tuple[object, ...] = ACTIVE_STATES
        if person is not None:
            query += " AND person=?"
            args = (*args, person)
        with self._lock:
            rows = self._conn.execute(query + " ORDER BY sent_at, instruction_id", args).fetchall()
        return [Survey.model_validate_json(r[0]) for r in rows]

    def record_reply(self, survey: Survey, time: float, text: str, effect: str) -> None:
        """The reply verbatim and the survey it changed, in one transaction."""
        with self._write() as db:
            db.execute(
                "INSERT INTO feedback_reply (instruction_id, person, time, text, effect)"
                " VALUES (?, ?, ?, ?, ?)",
                (survey.instruction_id, survey.person, time, text, effect),
            )
            self._put_survey(db, survey)

    def replies(self, instruction_id: str) -> list[tuple[float, str, str]]:
        """(time, text, effect) of every reply to a survey, oldest first."""
        with self._lock:
            rows = self._conn.execute(
                "SELECT time, text, effect FROM feedback_reply WHERE instruction_id=? ORDER BY seq",
                (instruction_id,),
            ).fetchall()
        return [(float(t), str(x), str(e)) for t, x, e in rows]

    # -- opt-outs ------------------------------------------------------------------------
    def opt_out(self, person: str, since: float) -> None:
        with self._write() as db:
            db.execute("INSERT OR IGNORE INTO feedback_optout VALUES (?, ?)", (person, since))

    def opt_in(self, person: str) -> None:
        with self._write() as db:
            db.execute("DELETE FROM feedback_optout WHERE person=?", (person,))

    def opted_out(self, person: str) -> bool:
        with self._lock:
            row = self._conn.execute(
                "SELECT 1 FROM feedback_optout WHERE person=?", (person,)
            ).fetchone()
        return row is not None

    def opted_out_people(self) -> list[str]:
        with self._lock:
            rows = self._conn.execute("SELECT person FROM feedback_optout ORDER BY person")
            return [str(r[0]) for r in rows.fetchall()]
