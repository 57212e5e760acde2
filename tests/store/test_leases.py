"""Leases with fencing tokens, on both backends: two replicas' connections to one database,
one of them paused past its lease's expiry while the other takes the office over."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from pathlib import Path

import psycopg
import pytest

from assistantx.core.errors import LeaseLostError
from assistantx.core.events import TraceEvent
from assistantx.store.journal import Journal
from assistantx.store.leases import Lease, Leases, fence
from assistantx.store.postgres_store import IDLE_IN_TRANSACTION_TIMEOUT_S, connect_postgres

TTL_S = 10.0


class Clock:
    """The replicas' shared wall clock, moved by the test (a pause is time passing)."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


@pytest.fixture
def clock() -> Clock:
    return Clock()


@pytest.fixture
def replicas(
    tmp_path: Path, database_url: str | None, clock: Clock
) -> Iterator[tuple[tuple[Leases, Journal], tuple[Leases, Journal]]]:
    """Two replicas, each with its own connections to the one database."""
    path = tmp_path / "journal.sqlite3"
    opened = [
        (
            Leases.open(path, database_url=database_url, clock=clock),
            Journal.open(path, database_url=database_url),
        )
        for _ in range(2)
    ]
    yield opened[0], opened[1]
    for leases, journal in opened:
        journal.close()
        leases.close()


def _event(step: int) -> TraceEvent:
    return TraceEvent(instruction_id="ins-1", kind="observation", time=float(step), step=step)


def test_a_held_office_is_not_given_to_another_until_its_lease_expires(
    replicas: tuple[tuple[Leases, Journal], ...], clock: Clock
) -> None:
    (a, _), (b, _) = replicas
    first = a.acquire("floor-3", "replica-a", TTL_S)
    assert first is not None and first.token == 1
    assert b.acquire("floor-3", "replica-b", TTL_S) is None
    clock.now += TTL_S / 2
    renewed = a.renew(first, TTL_S)
    assert renewed.token == 1 and renewed.expires_at == clock.now + TTL_S
    assert a.acquire("floor-3", "replica-a", TTL_S) == renewed  # its own: the same token
    clock.now += TTL_S * 0.9  # past the first expiry, not the renewed one
    assert b.acquire("floor-3", "replica-b", TTL_S) is None
    assert b.acquire("floor-2", "replica-b", TTL_S) is not None  # other offices are free
    clock.now += TTL_S  # A renews late, but nobody took the office meanwhile: still A's
    late = a.renew(renewed, TTL_S)
    assert late.token == 1 and late.expires_at == clock.now + TTL_S


def _a_holds_floor_3(leases: Leases, journal: Journal) -> Lease:
    """Replica A takes office floor-3 and its journal writes under that lease."""
    lease = leases.acquire("floor-3", "replica-a", TTL_S)
    assert lease is not None
    journal.hold(lease)
    return lease


def test_a_paused_replica_cannot_write_after_another_took_its_office(
    replicas: tuple[tuple[Leases, Journal], ...], clock: Clock
) -> None:
    (a_leases, a_journal), (b_leases, b_journal) = replicas
    a_lease = _a_holds_floor_3(a_leases, a_journal)
    a_journal.append_event(_event(1))  # A writes while it holds the office

    clock.now += TTL_S + 1  # A is paused past its expiry; B takes the office over
    b_lease = b_leases.acquire("floor-3", "replica-b", TTL_S)
    assert b_lease is not None and b_lease.token == a_lease.token + 1
    b_journal.hold(b_lease)
    b_journal.append_event(_event(2))

    # A wakes up, unaware: its writes carry the old token and are refused, nothing written.
    with pytest.raises(LeaseLostError, match="stale lease on office 'floor-3'"):
        a_journal.append_event(_event(3))
    with pytest.raises(LeaseLostError):
        a_journal.create_instruction("ins-2", "lee", "t", 1.0)
    with pytest.raises(LeaseLostError, match="was lost"):
        a_leases.renew(a_lease, TTL_S)
    assert [r.event.step for r in b_journal.events()] == [1, 2]
    assert b_journal.instruction("ins-2") is None


async def test_a_stale_awaited_write_is_refused_alone(
    replicas: tuple[tuple[Leases, Journal], ...], clock: Clock
) -> None:
    """Writes from the event loop share one group commit: the refused one fails alone."""
    (a_leases, a_journal), (b_leases, b_journal) = replicas
    _a_holds_floor_3(a_leases, a_journal)
    clock.now += TTL_S + 1
    assert b_leases.acquire("floor-3", "replica-b", TTL_S) is not None
    with pytest.raises(LeaseLostError):
        await a_journal.arecord(_event(1))
    a_journal.hold(None)  # writes that need no office (none here but the test's) still go
    assert await a_journal.arecord(_event(2)) > 0
    assert [r.event.step for r in b_journal.events()] == [2]


def test_a_released_office_goes_to_the_next_holder_with_a_new_token(
    replicas: tuple[tuple[Leases, Journal], ...],
) -> None:
    (a_leases, a_journal), (b_leases, _) = replicas
    a_lease = a_leases.acquire("floor-3", "replica-a", TTL_S)
    assert a_lease is not None
    a_journal.hold(a_lease)
    a_leases.release(a_lease)  # a clean shutdown hands the office over at once
    b_lease = b_leases.acquire("floor-3", "replica-b", TTL_S)
    assert b_lease is not None and b_lease.token == 2
    with pytest.raises(LeaseLostError):
        a_journal.append_event(_event(1))
    a_leases.release(a_lease)  # no longer A's: B keeps it
    assert [(x.holder, x.token) for x in b_leases.holders()] == [("replica-b", 2)]


@pytest.mark.postgres
def test_a_replica_paused_inside_a_write_does_not_hold_the_office_for_ever(
    postgres_url: str, clock: Clock
) -> None:
    """A paused in the middle of a journal write: its transaction holds the lease row FOR
    SHARE (the fence's check). The server ends that idle transaction, so B takes the office
    over, and nothing of A's half-done write lands."""
    path = Path("unused.sqlite3")
    a_leases = Leases.open(path, database_url=postgres_url, clock=clock)
    b_leases = Leases.open(path, database_url=postgres_url, clock=clock)
    a_conn = connect_postgres(postgres_url)
    try:
        a_lease = a_leases.acquire("floor-3", "replica-a", TTL_S)
        assert a_lease is not None
        a_conn.execute("CREATE TABLE writes (n INTEGER)")
        a_conn.execute("BEGIN")
        fence(a_lease, postgres=True)(a_conn)  # what every write under the lease runs first
        a_conn.execute("INSERT INTO writes VALUES (1)")
        # ... and A stops here, its transaction open.
        clock.now += TTL_S + 1
        taken: list[Lease | None] = []
        takeover = threading.Thread(
            target=lambda: taken.append(b_leases.acquire("floor-3", "replica-b", TTL_S))
        )
        takeover.start()
        takeover.join(timeout=IDLE_IN_TRANSACTION_TIMEOUT_S * 4)
        assert not takeover.is_alive(), "B's take-over still waits on A's paused transaction"
        assert taken[0] is not None and taken[0].token == a_lease.token + 1
        with pytest.raises(psycopg.errors.IdleInTransactionSessionTimeout):  # A wakes: ended
            a_conn.execute("COMMIT")
        assert a_conn.execute("SELECT count(*) FROM writes").fetchone()[0] == 0
    finally:
        a_conn.close()
        a_leases.close()
        b_leases.close()
