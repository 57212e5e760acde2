"""The stores' tests run on both backends: the embedded SQLite file and the tests' PostgreSQL."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from assistantx.store.journal import Journal

BACKENDS = ["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)]

OpenJournal = Callable[[], Journal]


@pytest.fixture(params=BACKENDS)
def backend(request: pytest.FixtureRequest) -> str:
    name: str = request.param
    return name


@pytest.fixture
def database_url(backend: str, request: pytest.FixtureRequest) -> str | None:
    """None for SQLite; a fresh PostgreSQL database's URL otherwise."""
    if backend == "sqlite":
        return None
    url: str = request.getfixturevalue("postgres_url")
    return url


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
