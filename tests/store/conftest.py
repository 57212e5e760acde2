"""The stores' tests run on both backends: the embedded SQLite file and the tests' PostgreSQL."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from assistantx.store.journal import Journal

OpenJournal = Callable[[], Journal]


@pytest.fixture
def open_journal(tmp_path: Path, database_url: str | None) -> Iterator[OpenJournal]:
    """Opens the test's one journal (again, after a close: the same file or database); every
    journal it opened is closed at the end."""
    opened: list[Journal] = []

    def open_() -> Journal:
        journal = Journal.open(tmp_path / "j.sqlite3", database_url=database_url)
        opened.append(journal)
        return journal

    yield open_
    for journal in opened:
        journal.close()
