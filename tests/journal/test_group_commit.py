"""The journal's writer thread: group commit, submission order, failures kept to their write."""

from __future__ import annotations

import asyncio
import sqlite3
from pathlib import Path

import pytest

from assistantx.journal import Journal
from assistantx.ppdr.events import TraceEvent


def _event(n: int) -> TraceEvent:
    return TraceEvent(instruction_id=f"ins-{n % 7}", kind="observation", time=float(n), step=n)


async def test_concurrent_writes_share_commits_and_keep_their_order(tmp_path: Path) -> None:
    journal = Journal.open(tmp_path / "j.sqlite3")
    seqs = await asyncio.gather(*(journal.arecord(_event(n)) for n in range(300)))
    assert seqs == sorted(seqs) and len(set(seqs)) == 300  # committed in submission order
    assert [r.event.step for r in journal.events(limit=1000)] == list(range(300))
    # 300 writes queued while the writer was busy are committed in far fewer transactions.
    assert journal.writer.writes == 300
    assert journal.writer.commits < 300
    journal.close()


async def test_a_failing_write_fails_alone(tmp_path: Path) -> None:
    journal = Journal.open(tmp_path / "j.sqlite3")

    def broken(db: sqlite3.Connection) -> None:
        db.execute("INSERT INTO no_such_table VALUES (1)")

    before = journal.arecord(_event(1))
    failing = journal.awrite(broken)
    after = journal.arecord(_event(2))
    results = await asyncio.gather(before, failing, after, return_exceptions=True)
    assert isinstance(results[1], sqlite3.OperationalError)
    assert [r.event.step for r in journal.events()] == [1, 2]
    journal.close()


def test_writes_queued_at_close_are_committed(tmp_path: Path) -> None:
    path = tmp_path / "j.sqlite3"
    journal = Journal.open(path)
    futures = [
        journal.writer.submit(
            lambda db, n=n: db.execute("INSERT INTO meta VALUES (?, 'x')", (f"k{n}",))
        )
        for n in range(50)
    ]
    journal.close()
    assert all(f.done() and f.exception() is None for f in futures)
    reopened = Journal.open(path)
    assert (
        reopened._conn.execute("SELECT COUNT(*) FROM meta WHERE key LIKE 'k%'").fetchone()[0] == 50
    )
    reopened.close()
    with pytest.raises(RuntimeError, match="closed"):
        journal.writer.submit(lambda db: None)
