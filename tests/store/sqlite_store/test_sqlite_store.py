"""The SQLite store helper: schema versions, one thread per file, the loop kept free, errors
back to their caller, close that commits what is queued."""

from __future__ import annotations

import asyncio
import sqlite3
import threading
from collections.abc import Callable
from pathlib import Path

import pytest

from assistantx.store.sqlite_store import Schema, SchemaError, SqliteStore, StoreClosedError

NOTES_V1 = "CREATE TABLE notes (id INTEGER PRIMARY KEY, text TEXT NOT NULL);"


def _add_author(db: sqlite3.Connection) -> None:
    db.execute("ALTER TABLE notes ADD COLUMN author TEXT NOT NULL DEFAULT 'nobody'")


V1 = Schema("notes", (NOTES_V1,))
V2 = Schema("notes", (NOTES_V1, _add_author))


def _versions(path: Path) -> dict[str, int]:
    with sqlite3.connect(path) as db:
        rows = db.execute("SELECT store, version FROM store_versions").fetchall()
    db.close()
    return {str(name): int(version) for name, version in rows}


def _insert(text: str) -> Callable[[sqlite3.Connection], int | None]:
    return lambda db: db.execute("INSERT INTO notes (text) VALUES (?)", (text,)).lastrowid


def _texts(db: sqlite3.Connection) -> list[str]:
    return [str(r[0]) for r in db.execute("SELECT text FROM notes ORDER BY id")]


def test_a_new_file_gets_every_migration_and_wal(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    store = SqliteStore.open(path, V2)
    store.call(lambda db: db.execute("INSERT INTO notes (text, author) VALUES ('a', 'lee')"))
    assert store.call(lambda db: db.execute("PRAGMA journal_mode").fetchone()[0]) == "wal"
    store.close()
    assert _versions(path) == {"notes": 2}


def test_reopening_runs_only_the_missing_migrations(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    store = SqliteStore.open(path, V1)
    store.call(_insert("kept"))
    store.close()
    assert _versions(path) == {"notes": 1}
    # Version 1 again would fail: the table exists. Only the column is added.
    store = SqliteStore.open(path, V2)
    rows = store.call(lambda db: db.execute("SELECT text, author FROM notes").fetchall())
    assert [tuple(r) for r in rows] == [("kept", "nobody")]
    store.close()
    assert _versions(path) == {"notes": 2}


def test_a_file_from_a_newer_version_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    SqliteStore.open(path, V2).close()
    with pytest.raises(SchemaError, match="notes schema 2, this version reads 1"):
        SqliteStore.open(path, V1)


def test_a_failing_migration_leaves_the_file_as_it_was(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    SqliteStore.open(path, V1).close()

    def broken(db: sqlite3.Connection) -> None:
        db.execute("CREATE TABLE extra (x)")
        db.execute("ALTER TABLE no_such_table ADD COLUMN y")

    with pytest.raises(sqlite3.OperationalError, match="no_such_table"):
        SqliteStore.open(path, Schema("notes", (NOTES_V1, _add_author, broken)))
    assert _versions(path) == {"notes": 1}
    with sqlite3.connect(path) as db:
        tables = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type='table'")}
        columns = {r[1] for r in db.execute("PRAGMA table_info(notes)")}
    db.close()
    assert "extra" not in tables and "author" not in columns


def test_stores_sharing_a_file_keep_their_own_versions(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    other = Schema(
        "tags", ("CREATE TABLE tags (name TEXT); CREATE INDEX tags_name ON tags (name)",)
    )
    notes, tags = SqliteStore.open(path, V2), SqliteStore.open(path, other)
    tags.call(lambda db: db.execute("INSERT INTO tags VALUES ('x')"))
    notes.call(_insert("n"))
    notes.close()
    tags.close()
    assert _versions(path) == {"notes": 2, "tags": 1}


def test_a_file_that_is_not_sqlite_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    path.write_bytes(b"not a database " * 100)
    with pytest.raises(sqlite3.DatabaseError):
        SqliteStore.open(path, V1)


async def test_a_slow_write_does_not_hold_the_event_loop(tmp_path: Path) -> None:
    """The write cannot finish until a coroutine has run on the loop while it is under way:
    if awaiting it held the loop, the write would wait out its five seconds and fail."""
    store = SqliteStore.open(tmp_path / "s.sqlite3", V1)
    started, released = threading.Event(), threading.Event()

    def slow(db: sqlite3.Connection) -> bool:
        db.execute("INSERT INTO notes (text) VALUES ('slow')")
        started.set()
        return released.wait(5)

    async def meanwhile() -> None:
        assert await asyncio.to_thread(started.wait, 5)
        released.set()

    finished, _ = await asyncio.gather(store.acall(slow), meanwhile())
    assert finished is True
    assert store.call(_texts) == ["slow"]
    await store.aclose()


async def test_concurrent_calls_share_commits_in_their_order(tmp_path: Path) -> None:
    store = SqliteStore.open(tmp_path / "s.sqlite3", V1)
    ids = await asyncio.gather(*(store.acall(_insert(f"n{k}")) for k in range(200)))
    assert ids == list(range(1, 201))
    assert store.call(_texts) == [f"n{k}" for k in range(200)]
    assert store.writes == 201 and store.commits < 200
    store.close()


async def test_an_error_reaches_its_caller_and_rolls_back_only_its_call(tmp_path: Path) -> None:
    store = SqliteStore.open(tmp_path / "s.sqlite3", V1)

    def half_then_fail(db: sqlite3.Connection) -> None:
        db.execute("INSERT INTO notes (text) VALUES ('half')")
        raise ValueError("the caller's own check failed")

    results = await asyncio.gather(
        store.acall(_insert("before")),
        store.acall(half_then_fail),
        store.acall(lambda db: db.execute("INSERT INTO nowhere VALUES (1)")),
        store.acall(_insert("after")),
        return_exceptions=True,
    )
    assert isinstance(results[1], ValueError) and "own check" in str(results[1])
    assert isinstance(results[2], sqlite3.OperationalError)
    assert store.call(_texts) == ["before", "after"]
    with pytest.raises(ValueError, match="own check"):
        store.call(half_then_fail)
    store.close()


async def test_close_commits_what_is_queued_and_is_idempotent(tmp_path: Path) -> None:
    path = tmp_path / "s.sqlite3"
    store = SqliteStore.open(path, V1)
    from_loop = [store.submit(_insert(f"loop{k}")) for k in range(20)]  # not yet handed over
    from_thread = await asyncio.to_thread(lambda: store.submit(_insert("thread")))
    store.close()
    store.close()
    await store.aclose()
    assert all(f.done() and f.exception() is None for f in [*from_loop, from_thread])
    with pytest.raises(StoreClosedError, match="closed"):
        store.submit(_insert("late"))
    with pytest.raises(StoreClosedError):
        await store.acall(_insert("late"))
    reopened = SqliteStore.open(path, V1)
    # What the loop queued first is committed first, then the thread's.
    assert reopened.call(_texts) == [*(f"loop{k}" for k in range(20)), "thread"]
    reopened.close()


def test_sync_calls_from_threads_are_serialised(tmp_path: Path) -> None:
    store = SqliteStore.open(tmp_path / "s.sqlite3", V1)

    def add_many(who: str) -> None:
        for k in range(50):
            store.call(_insert(f"{who}{k}"))

    threads = [threading.Thread(target=add_many, args=(w,)) for w in "abc"]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    texts = store.call(_texts)
    assert sorted(texts) == sorted(f"{w}{k}" for w in "abc" for k in range(50))
    for w in "abc":  # each thread's writes in its own order
        assert [t for t in texts if t[0] == w] == [f"{w}{k}" for k in range(50)]
    store.close()


async def test_a_caller_cancelled_while_waiting_leaves_the_store_working(tmp_path: Path) -> None:
    """Its write is still committed, in order, and later calls are served (the journal's old
    writer thread died setting the result of the cancelled future, and every later call hung)."""
    store = SqliteStore.open(tmp_path / "s.sqlite3", V1)
    busy, release = threading.Event(), threading.Event()

    def hold(db: sqlite3.Connection) -> None:
        busy.set()
        release.wait(5)

    held = store.submit(hold, now=True)
    assert await asyncio.to_thread(busy.wait, 5)
    # What ``acall`` does, in steps the test can order: the write joins this loop's batch,
    # a blocking submit hands that batch to the thread (queued behind ``hold``), and the
    # caller stops waiting.
    waiting = asyncio.wrap_future(store.submit(_insert("cancelled caller")))
    handed_over = store.submit(_texts, now=True)
    waiting.cancel()
    with pytest.raises(asyncio.CancelledError):
        await waiting
    release.set()
    held.result()
    assert handed_over.result() == ["cancelled caller"]
    after = await asyncio.wait_for(store.acall(_insert("later")), 10)  # a guard, not a timing
    assert after == 2
    assert store.call(_texts) == ["cancelled caller", "later"]
    store.close()
