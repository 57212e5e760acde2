"""The journal on both backends: instructions, events, messages with idempotency, state; and
the files or databases it refuses."""

from __future__ import annotations

from datetime import UTC, datetime
from pathlib import Path

import pytest

from assistantx.core.errors import JournalError
from assistantx.core.events import TraceEvent
from assistantx.core.ports.messenger import ChatRef, InboundMessage, OutboundMessage
from assistantx.core.trace import Trace
from assistantx.memory.short_term import ShortTermMemory
from assistantx.store.journal import Journal
from store.conftest import OpenJournal


def _stm(iid: str = "ins-1") -> ShortTermMemory:
    trace = Trace(instruction_id=iid, requester="lee", text="t", reasoner="x", started_at=1.0)
    return ShortTermMemory(instruction_id=iid, requester="lee", text="t", trace=trace)


def test_instruction_lifecycle_survives_reopening(open_journal: OpenJournal) -> None:
    journal = open_journal()
    journal.create_instruction("ins-1", "lee", "t", 1.0)
    event = TraceEvent(instruction_id="ins-1", kind="step_started", time=2.0, step=0)
    seq = journal.record(event, stm=_stm(), status="running", states={"w": {"a": 1}})
    journal.close()
    journal = open_journal()
    record = journal.instruction("ins-1")
    assert record is not None and record.status == "running" and record.stm is not None
    assert [r.seq for r in journal.events("ins-1")] == [seq]
    assert journal.state("w") == {"a": 1}
    assert [r.id for r in journal.unfinished()] == ["ins-1"]


def test_listing_filters_and_pages_newest_first(open_journal: OpenJournal) -> None:
    journal = open_journal()
    for n in range(5):
        journal.create_instruction(f"ins-{n}", "lee" if n % 2 else "zhang", "t", float(n))
    first = journal.instructions(limit=2)
    assert [r.id for r in first] == ["ins-4", "ins-3"]
    rest = journal.instructions(after_seq=first[-1].seq, limit=10)
    assert [r.id for r in rest] == ["ins-2", "ins-1", "ins-0"]
    assert [r.id for r in journal.instructions(requester="lee")] == ["ins-3", "ins-1"]
    assert journal.count_by_status() == {"queued": 5}


def test_outbound_keys_and_inbound_event_ids_deduplicate(open_journal: OpenJournal) -> None:
    journal = open_journal()
    message = OutboundMessage(chat=ChatRef(kind="dm", id="lee"), text="hi", idempotency_key="k1")
    first = journal.record_outbound(message, "assistant", 1.0)
    journal.mark_sent(first.seq, "m-1")
    again = journal.record_outbound(message, "assistant", 2.0)
    assert again.seq == first.seq and again.status == "sent"
    inbound = InboundMessage(
        platform="p",
        event_id="e1",
        chat=ChatRef(kind="dm", id="lee"),
        sender="lee",
        text="yo",
        time=datetime.fromtimestamp(3, tz=UTC),
    )
    assert journal.record_inbound(inbound) is not None
    assert journal.record_inbound(inbound) is None
    assert [m.direction for m in journal.messages(ChatRef(kind="dm", id="lee"))] == ["out", "in"]


def test_a_file_that_is_not_a_journal_is_a_clear_error(tmp_path: Path) -> None:
    path = tmp_path / "j.sqlite3"
    path.write_bytes(b"this is not sqlite" * 100)
    with pytest.raises(JournalError, match="not a usable journal"):
        Journal.open(path)


def test_the_step_count_is_kept_for_lists(open_journal: OpenJournal) -> None:
    from assistantx.core.trace import TraceStep

    journal = open_journal()
    journal.create_instruction("ins-1", "lee", "t", 1.0)
    stm = _stm()
    for n in range(3):
        stm.trace.steps.append(TraceStep(index=n, started_at=2.0 + n))
        event = TraceEvent(instruction_id="ins-1", kind="step_started", time=2.0 + n, step=n)
        journal.record(event, stm=stm, status="running")
    [listed] = journal.instructions()
    assert listed.stm is None and listed.steps == 3


def test_a_journal_written_before_the_step_count_opens(tmp_path: Path) -> None:
    import sqlite3

    from assistantx.store.journal._schema import SCHEMA

    path = tmp_path / "old.sqlite3"
    old_schema = SCHEMA.replace(",\n    steps      INTEGER NOT NULL DEFAULT 0", "")
    assert old_schema != SCHEMA
    with sqlite3.connect(path) as db:
        db.executescript(old_schema)
        db.execute("INSERT INTO meta VALUES ('schema', '1')")
        db.execute(
            "INSERT INTO instructions (id, requester, text, status, created_at, updated_at)"
            " VALUES ('ins-0', 'lee', 't', 'done', 1.0, 1.0)"
        )
    db.close()
    journal = Journal.open(path)
    [listed] = journal.instructions()
    assert (listed.id, listed.steps) == ("ins-0", 0)
    journal.checkpoint(_stm("ins-0"), "done")
    journal.close()


def test_inserting_a_taken_instruction_id_raises_instead_of_overwriting(
    open_journal: OpenJournal,
) -> None:
    journal = open_journal()
    journal.create_instruction("ins-1", "lee", "lee's own", 1.0)
    with pytest.raises(JournalError, match="taken"):
        journal.create_instruction("ins-1", "zhang", "zhang's", 2.0)
    zhangs = _stm("ins-1").model_copy(update={"requester": "zhang", "text": "zhang's"})
    with pytest.raises(JournalError, match="taken"):
        journal.insert_instruction(zhangs)
    with pytest.raises(JournalError, match="taken"):  # a checkpoint of another requester's
        journal.checkpoint(zhangs, "running")
    record = journal.instruction("ins-1")
    assert record is not None
    assert (record.requester, record.text, record.status) == ("lee", "lee's own", "queued")
    journal.checkpoint(_stm("ins-1"), "running")  # its own row: an update
    record = journal.instruction("ins-1")
    assert record is not None and record.status == "running" and record.requester == "lee"


def test_a_journal_from_a_newer_version_is_refused(tmp_path: Path) -> None:
    import sqlite3

    path = tmp_path / "j.sqlite3"
    Journal.open(path).close()
    with sqlite3.connect(path) as db:
        db.execute("UPDATE store_versions SET version=2 WHERE store='journal'")
    db.close()
    with pytest.raises(JournalError, match="journal schema 2, this version reads 1"):
        Journal.open(path)
    # A file from before the versions table, whose own record says a newer schema.
    old = tmp_path / "old.sqlite3"
    with sqlite3.connect(old) as db:
        db.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
        db.execute("INSERT INTO meta VALUES ('schema', '2')")
    db.close()
    with pytest.raises(JournalError, match="journal schema 2, this version reads 1"):
        Journal.open(old)
    with sqlite3.connect(old) as db:  # the refused migration left nothing behind
        tables = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type='table'")}
    db.close()
    assert tables == {"meta"}


@pytest.mark.postgres
def test_a_database_from_a_newer_version_is_refused(postgres_url: str, tmp_path: Path) -> None:
    import psycopg

    Journal.open(tmp_path / "unused", database_url=postgres_url).close()
    with psycopg.connect(postgres_url, autocommit=True) as db:
        db.execute("UPDATE store_versions SET version=2 WHERE store='journal'")
    with pytest.raises(JournalError, match="journal schema 2, this version reads 1 at most"):
        Journal.open(tmp_path / "unused", database_url=postgres_url)


@pytest.mark.postgres
def test_a_database_that_cannot_be_reached_is_a_clear_error_without_its_password(
    tmp_path: Path,
) -> None:
    from helpers.servers import refusing_port

    with refusing_port() as port:
        url = f"postgresql://lee:secret@127.0.0.1:{port}/nowhere"
        with pytest.raises(JournalError, match="not a usable journal") as raised:
            Journal.open(tmp_path / "unused", database_url=url)
    assert "secret" not in str(raised.value)
    assert str(raised.value).startswith("postgresql://lee@127.0.0.1:")


def test_memory_updates_snapshots_chats_and_cancels(open_journal: OpenJournal) -> None:
    journal = open_journal()
    journal.record_memory_update(1.0, "ins-1", {"op": "available", "person": "lee"})
    journal.put_memory_snapshot("memory", {"graph": 1})
    journal.record_memory_update(2.0, None, {"op": "owns", "person": "zhang"})
    snapshot = journal.state("memory")
    assert snapshot is not None and snapshot["graph"] == 1
    assert journal.memory_updates_after(snapshot["through"]) == [{"op": "owns", "person": "zhang"}]
    assert len(journal.memory_updates()) == 2
    journal.put_states({"world": {"robot": "dock"}, "sim": {"t": 1.5}})
    assert journal.state("sim") == {"t": 1.5} and journal.state("none") is None

    journal.create_instruction("ins-1", "lee", "t", 1.0)
    journal.request_cancel("ins-1")
    record = journal.instruction("ins-1")
    assert record is not None and record.cancel_requested
    journal.set_status("ins-1", "cancelled")
    assert journal.count_by_status() == {"cancelled": 1}
    for n, chat in enumerate(("lee", "zhang", "lee")):
        message = OutboundMessage(chat=ChatRef(kind="dm", id=chat), text=f"m{n}",
                                  instruction_id="ins-1")  # fmt: skip
        journal.record_outbound(message, "assistant", 10.0 + n)
    assert [(c.chat.id, c.messages, c.last_time) for c in journal.chats()] == [
        ("lee", 2, 12.0),
        ("zhang", 1, 11.0),
    ]
    assert [m.text for m in journal.messages_of("ins-1")] == ["m0", "m1", "m2"]
    for step in range(3):
        journal.append_event(
            TraceEvent(instruction_id="ins-1", kind="observation", time=5.0 + step)
        )
    first = journal.events("ins-1")[0].seq
    assert journal.event_seq_before(6.0) == first and journal.last_event_seq() == first + 2


@pytest.mark.postgres
def test_a_journal_connects_again_after_the_server_dropped_its_connections(
    postgres_url: str, tmp_path: Path
) -> None:
    """A database restart or fail-over drops every connection: the write and the read that
    find theirs broken fail, the next ones connect again (the writer thread lives on)."""
    import psycopg

    journal = Journal.open(tmp_path / "unused", database_url=postgres_url)
    journal.create_instruction("ins-1", "lee", "t", 1.0)
    with psycopg.connect(postgres_url, autocommit=True) as admin:
        admin.execute(
            "SELECT pg_terminate_backend(pid) FROM pg_stat_activity"
            " WHERE datname = current_database() AND pid <> pg_backend_pid()"
        )
    with pytest.raises(psycopg.OperationalError):
        journal.create_instruction("ins-2", "lee", "t", 2.0)
    with pytest.raises(psycopg.OperationalError):
        journal.instruction("ins-1")
    journal.create_instruction("ins-3", "lee", "t", 3.0)
    assert [r.id for r in journal.instructions()] == ["ins-3", "ins-1"]
    journal.close()
