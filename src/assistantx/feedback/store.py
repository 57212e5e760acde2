"""Survey answers, opt-outs and per-instruction impact, kept in the service's SQLite journal.

The tables (prefixed ``feedback_``) live in the journal's file next to its own tables, so an
instruction, its survey and its walking figures are backed up and restored together. This
module opens its own connection (WAL lets several connections share the file) and creates its
tables when missing (store ``feedback`` in the file's schema versions); it never touches the
journal's tables.

Every reply a person sends to a survey is stored verbatim with what it did, so a reply that
could not be read is never lost.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from assistantx.core.errors import JournalError
from assistantx.feedback.impact import InstructionRecord
from assistantx.feedback.survey import Survey, SurveyState
from assistantx.store.sqlite_store import Schema, SchemaError, SqliteStore

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
T = TypeVar("T")
FEEDBACK_SCHEMA = Schema("feedback", (_SCHEMA,))
ACTIVE_STATES = (SurveyState.OPEN.value, SurveyState.COMPLETE.value)


Job = Callable[[sqlite3.Connection], T]


class FeedbackStore:
    """``FeedbackStore.open(path)`` on the journal file (or any SQLite file); ``close()`` it.

    Every call runs on the store's own thread (``core.sqlite_store``), one transaction per
    write. The plain methods block their thread (the CLI, the report on a worker thread,
    tests); code on the event loop awaits the ``a``-prefixed ones (the Surveyor)."""

    def __init__(self, db: SqliteStore) -> None:
        self._db = db
        self.path = db.path

    @classmethod
    def open(cls, path: Path) -> FeedbackStore:
        try:
            # As durable as the journal's own tables (a kill -9 loses nothing committed); FULL
            # would fsync on every commit, and a reminder tick commits once per survey.
            db = SqliteStore.open(path, FEEDBACK_SCHEMA, synchronous="NORMAL")
        except (sqlite3.DatabaseError, SchemaError) as exc:
            raise JournalError(f"{path}: cannot hold survey data ({exc})") from exc
        return cls(db)

    def close(self) -> None:
        """Commits what is queued, then closes; a second call does nothing."""
        self._db.close()

    # -- instructions --------------------------------------------------------------------
    def put_instruction(self, record: InstructionRecord) -> None:
        self._db.call(_put_instruction(record))

    async def aput_instruction(self, record: InstructionRecord) -> None:
        await self._db.acall(_put_instruction(record))

    def instruction(self, instruction_id: str) -> InstructionRecord | None:
        return self._db.call(_instruction(instruction_id))

    def instructions(
        self, start: float | None = None, end: float | None = None
    ) -> list[InstructionRecord]:
        """Instructions that ended in [start, end), oldest first."""
        return self._db.call(_instructions(start, end))

    # -- surveys -------------------------------------------------------------------------
    def put_survey(self, survey: Survey) -> None:
        self._db.call(_put_survey(survey))

    async def aput_survey(self, survey: Survey) -> None:
        await self._db.acall(_put_survey(survey))

    def survey(self, instruction_id: str) -> Survey | None:
        return self._db.call(_survey(instruction_id))

    async def asurvey(self, instruction_id: str) -> Survey | None:
        return await self._db.acall(_survey(instruction_id))

    def surveys(self, instruction_ids: list[str] | None = None) -> list[Survey]:
        surveys = self._db.call(_all_surveys)
        if instruction_ids is None:
            return surveys
        wanted = set(instruction_ids)
        return [s for s in surveys if s.instruction_id in wanted]

    def active_surveys(self, person: str | None = None) -> list[Survey]:
        """Surveys that may still take replies (open, or complete awaiting a comment)."""
        return self._db.call(_active_surveys(person))

    async def aactive_surveys(self, person: str | None = None) -> list[Survey]:
        return await self._db.acall(_active_surveys(person))

    def record_reply(self, survey: Survey, time: float, text: str, effect: str) -> None:
        """The reply verbatim and the survey it changed, in one transaction."""
        self._db.call(_record_reply(survey, time, text, effect))

    async def arecord_reply(self, survey: Survey, time: float, text: str, effect: str) -> None:
        await self._db.acall(_record_reply(survey, time, text, effect))

    def replies(self, instruction_id: str) -> list[tuple[float, str, str]]:
        """(time, text, effect) of every reply to a survey, oldest first."""
        return self._db.call(_replies(instruction_id))

    async def areplies(self, instruction_id: str) -> list[tuple[float, str, str]]:
        return await self._db.acall(_replies(instruction_id))

    # -- opt-outs ------------------------------------------------------------------------
    def opt_out(self, person: str, since: float) -> None:
        self._db.call(_opt_out(person, since))

    async def aopt_out(self, person: str, since: float) -> None:
        await self._db.acall(_opt_out(person, since))

    def opt_in(self, person: str) -> None:
        self._db.call(_opt_in(person))

    async def aopt_in(self, person: str) -> None:
        await self._db.acall(_opt_in(person))

    def opted_out(self, person: str) -> bool:
        return self._db.call(_opted_out(person))

    async def aopted_out(self, person: str) -> bool:
        return await self._db.acall(_opted_out(person))

    def opted_out_people(self) -> list[str]:
        rows = self._db.call(
            lambda db: db.execute("SELECT person FROM feedback_optout ORDER BY person").fetchall()
        )
        return [str(r[0]) for r in rows]


# -- the calls: each takes its arguments now (a survey goes on changing once the caller
# continues) and runs on the store's thread ---------------------------------------------------
def _put_instruction(record: InstructionRecord) -> Job[None]:
    row = (record.instruction_id, record.requester, record.ended_at, record.model_dump_json())

    def write(db: sqlite3.Connection) -> None:
        db.execute("INSERT OR REPLACE INTO feedback_instruction VALUES (?, ?, ?, ?)", row)

    return write


def _instruction(instruction_id: str) -> Job[InstructionRecord | None]:
    def read(db: sqlite3.Connection) -> InstructionRecord | None:
        row = db.execute(
            "SELECT body FROM feedback_instruction WHERE instruction_id=?", (instruction_id,)
        ).fetchone()
        return InstructionRecord.model_validate_json(row[0]) if row else None

    return read


def _instructions(start: float | None, end: float | None) -> Job[list[InstructionRecord]]:
    lo = float("-inf") if start is None else start
    hi = float("inf") if end is None else end

    def read(db: sqlite3.Connection) -> list[InstructionRecord]:
        rows = db.execute(
            "SELECT body FROM feedback_instruction WHERE ended_at >= ? AND ended_at < ?"
            " ORDER BY ended_at, instruction_id",
            (lo, hi),
        ).fetchall()
        return [InstructionRecord.model_validate_json(r[0]) for r in rows]

    return read


def _survey_row(survey: Survey) -> tuple[str, str, str, float, str]:
    return (
        survey.instruction_id,
        survey.person,
        survey.state.value,
        survey.sent_at,
        survey.model_dump_json(),
    )


def _put_survey(survey: Survey) -> Job[None]:
    row = _survey_row(survey)

    def write(db: sqlite3.Connection) -> None:
        db.execute("INSERT OR REPLACE INTO feedback_survey VALUES (?, ?, ?, ?, ?)", row)

    return write


def _survey(instruction_id: str) -> Job[Survey | None]:
    def read(db: sqlite3.Connection) -> Survey | None:
        row = db.execute(
            "SELECT body FROM feedback_survey WHERE instruction_id=?", (instruction_id,)
        ).fetchone()
        return Survey.model_validate_json(row[0]) if row else None

    return read


def _all_surveys(db: sqlite3.Connection) -> list[Survey]:
    rows = db.execute("SELECT body FROM feedback_survey ORDER BY sent_at, instruction_id")
    return [Survey.model_validate_json(r[0]) for r in rows.fetchall()]


def _active_surveys(person: str | None) -> Job[list[Survey]]:
    query = "SELECT body FROM feedback_survey WHERE state IN (?, ?)"
    args: tuple[object, ...] = ACTIVE_STATES
    if person is not None:
        query += " AND person=?"
        args = (*args, person)
    query += " ORDER BY sent_at, instruction_id"

    def read(db: sqlite3.Connection) -> list[Survey]:
        return [Survey.model_validate_json(r[0]) for r in db.execute(query, args).fetchall()]

    return read


def _record_reply(survey: Survey, time: float, text: str, effect: str) -> Job[None]:
    reply = (survey.instruction_id, survey.person, time, text, effect)
    put = _put_survey(survey)

    def write(db: sqlite3.Connection) -> None:
        db.execute(
            "INSERT INTO feedback_reply (instruction_id, person, time, text, effect)"
            " VALUES (?, ?, ?, ?, ?)",
            reply,
        )
        put(db)

    return write


def _replies(instruction_id: str) -> Job[list[tuple[float, str, str]]]:
    def read(db: sqlite3.Connection) -> list[tuple[float, str, str]]:
        rows = db.execute(
            "SELECT time, text, effect FROM feedback_reply WHERE instruction_id=? ORDER BY seq",
            (instruction_id,),
        ).fetchall()
        return [(float(t), str(x), str(e)) for t, x, e in rows]

    return read


def _opt_out(person: str, since: float) -> Job[None]:
    def write(db: sqlite3.Connection) -> None:
        db.execute("INSERT OR IGNORE INTO feedback_optout VALUES (?, ?)", (person, since))

    return write


def _opt_in(person: str) -> Job[None]:
    def write(db: sqlite3.Connection) -> None:
        db.execute("DELETE FROM feedback_optout WHERE person=?", (person,))

    return write


def _opted_out(person: str) -> Job[bool]:
    def read(db: sqlite3.Connection) -> bool:
        return (
            db.execute("SELECT 1 FROM feedback_optout WHERE person=?", (person,)).fetchone()
            is not None
        )

    return read
