"""One transaction helper for both backends: the block is committed whole, or rolled back
whole on any error (an interrupt too), and the error is raised again."""

from __future__ import annotations

import sqlite3
from collections.abc import Iterator
from pathlib import Path

import pytest

from assistantx.store.connection import TransactedConnection, transaction
from assistantx.store.postgres_store import connect_postgres


@pytest.fixture
def conn(tmp_path: Path, database_url: str | None) -> Iterator[TransactedConnection]:
    """A connection with one empty table, transactions explicit, on the test's backend."""
    if database_url is None:
        lite = sqlite3.connect(tmp_path / "t.sqlite3", isolation_level=None)
        lite.execute("CREATE TABLE notes (text TEXT)")
        yield lite
        lite.close()
        return
    pg = connect_postgres(database_url)
    pg.execute("CREATE TABLE notes (text TEXT)")
    yield pg
    pg.close()


def _notes(conn: TransactedConnection) -> list[str]:
    return [row[0] for row in conn.execute("SELECT text FROM notes ORDER BY text").fetchall()]


def test_the_block_is_committed(conn: TransactedConnection) -> None:
    with transaction(conn):
        conn.execute("INSERT INTO notes VALUES (?)", ("a",))
        conn.execute("INSERT INTO notes VALUES (?)", ("b",))
    assert not conn.in_transaction
    assert _notes(conn) == ["a", "b"]


@pytest.mark.parametrize("error", [ValueError("bad migration"), KeyboardInterrupt()])
def test_an_error_rolls_the_whole_block_back_and_is_raised(
    conn: TransactedConnection, error: BaseException
) -> None:
    def write_then_fail() -> None:
        with transaction(conn):
            conn.execute("INSERT INTO notes VALUES (?)", ("a",))
            raise error

    with pytest.raises(type(error)):
        write_then_fail()
    assert not conn.in_transaction
    assert _notes(conn) == []
