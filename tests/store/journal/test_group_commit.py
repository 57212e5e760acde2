"""The journal's writer thread: group commit, submission order, failures kept to their write."""

from __future__ import annotations

import asyncio
import time

import pytest

from assistantx.core.events import TraceEvent
from assistantx.core.ports.messenger import ChatRef, OutboundMessage
from assistantx.core.trace import Trace
from assistantx.memory.short_term import ShortTermMemory
from assistantx.store.connection import Connection, database_errors
from store.conftest import OpenJournal


def _event(n: int) -> TraceEvent:
    return TraceEvent(instruction_id=f"ins-{n % 7}", kind="observation", time=float(n), step=n)


async def test_concurrent_writes_share_commits_and_keep_their_order(
    open_journal: OpenJournal,
) -> None:
    journal = open_journal()
    seqs = await asyncio.gather(*(journal.arecord(_event(n)) for n in range(300)))
    assert seqs == sorted(seqs) and len(set(seqs)) == 300  # committed in submission order
    assert [r.event.step for r in journal.events(limit=1000)] == list(range(300))
    # 300 writes queued while the writer was busy are committed in far fewer transactions.
    assert journal.writer.writes == 300
    assert journal.writer.commits < 300
    journal.close()


async def test_a_failing_write_fails_alone(open_journal: OpenJournal) -> None:
    journal = open_journal()

    def broken(db: Connection) -> None:
        db.execute("INSERT INTO no_such_table VALUES (1)")

    before = journal.arecord(_event(1))
    failing = journal.awrite(broken)
    after = journal.arecord(_event(2))
    results = await asyncio.gather(before, failing, after, return_exceptions=True)
    assert isinstance(results[1], database_errors())
    assert [r.event.step for r in journal.events()] == [1, 2]
    journal.close()


def test_writes_queued_at_close_are_committed(open_journal: OpenJournal) -> None:
    journal = open_journal()
    futures = [
        journal.writer.submit(
            lambda db, n=n: db.execute("INSERT INTO meta VALUES (?, 'x')", (f"k{n}",))
        )
        for n in range(50)
    ]
    journal.close()
    assert all(f.done() and f.exception() is None for f in futures)
    reopened = open_journal()
    assert (
        reopened._conn.execute("SELECT COUNT(*) FROM meta WHERE key LIKE 'k%'").fetchone()[0] == 50
    )
    with pytest.raises(RuntimeError, match="closed"):
        journal.writer.submit(lambda db: None)


def test_compaction_drops_old_traces_and_keeps_outcomes_and_messages(
    open_journal: OpenJournal,
) -> None:
    journal = open_journal()
    for iid in ("ins-old", "ins-new"):
        trace = Trace(instruction_id=iid, requester="lee", text="t", reasoner="x", started_at=1)
        stm = ShortTermMemory(instruction_id=iid, requester="lee", text="t", trace=trace)
        stm.trace.outcome, stm.trace.summary = "done", "brought the stapler"
        journal.record(TraceEvent(instruction_id=iid, kind="step_started", time=1.0, step=0))
        journal.checkpoint(stm, "done")
        message = OutboundMessage(
            chat=ChatRef(kind="dm", id="lee"),
            text="done",
            idempotency_key=f"{iid}:end",
            instruction_id=iid,
        )
        journal.record_outbound(message, "assistant", 1.0)
    cut = time.time() + 1  # both ended before it ...
    journal.write(lambda db: db.execute("UPDATE instructions SET updated_at=0 WHERE id='ins-old'"))
    assert journal.compact(finished_before=10.0) == 1  # ... but only ins-old ended before 10
    old, new = journal.instruction("ins-old"), journal.instruction("ins-new")
    assert old is not None and new is not None
    assert (old.status, old.outcome, old.summary) == ("done", "done", "brought the stapler")
    assert old.stm is None and journal.events("ins-old") == []
    assert new.stm is not None and len(journal.events("ins-new")) == 1
    assert [m.text for m in journal.messages_of("ins-old")] == ["done"]  # the audit stays
    assert journal.compact(finished_before=cut) == 1 and journal.compact(cut) == 0
    journal.close()


async def test_a_writer_cancelled_while_waiting_does_not_stop_the_journal(
    open_journal: OpenJournal,
) -> None:
    """An instruction cancelled (or cut off at its wall-clock bound) while awaiting its write:
    the write is still committed, and the writer thread keeps serving (the old writer thread
    died setting the result of the cancelled future, and every later write hung)."""
    journal = open_journal()
    waiting = asyncio.create_task(journal.arecord(_event(1)))
    await asyncio.sleep(0)  # submitted: it waits for the hand-over to the writer
    waiting.cancel()
    with pytest.raises(asyncio.CancelledError):
        await waiting
    await asyncio.wait_for(journal.arecord(_event(2)), 10)  # a guard against a hang only
    assert [r.event.step for r in journal.events()] == [1, 2]
    journal.close()


async def test_queued_states_are_ordered_before_every_later_write(
    open_journal: OpenJournal,
) -> None:
    journal = open_journal()
    written = journal.queue_states({"lock_codes": {"codes": {"c1": ["scanned", 9.0]}}})
    assert not written.done()  # returned without waiting for the writer
    # What acts on the event journals after it: once that is committed, so is the state.
    await journal.arecord(_event(1))
    assert written.done() and written.exception() is None
    assert journal.state("lock_codes") == {"codes": {"c1": ["scanned", 9.0]}}
    journal.close()
