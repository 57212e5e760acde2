"""The spread of offices over replicas, round by round, on the real leases table (SQLite here;
the same statements run on PostgreSQL in test_office_replicas.py), with the replicas' clock
in the test's hands: no waiting for an expiry."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.service.offices.balancer import Balancer, fair_share, try_order
from assistantx.store.leases import Lease, Leases

OFFICES = ["annex", "harbour", "hq"]
TTL_S = 30.0


class Replica:
    """A replica's office host: what the balancer started and stopped on it."""

    def __init__(self, path: Path, name: str, now: list[float]) -> None:
        self.leases = Leases.open(path, clock=lambda: now[0])
        self.running: dict[str, Lease] = {}
        self.balancer = Balancer(
            self.leases,
            OFFICES,
            name,
            TTL_S,
            start_office=self.start,
            stop_office=self.stop,
            held=lambda: set(self.running),
            clock=lambda: now[0],
        )

    async def start(self, office: str, lease: Lease) -> None:
        self.running[office] = lease

    async def stop(self, office: str) -> None:
        self.leases.release(self.running.pop(office))


@pytest.mark.parametrize(
    ("offices", "replicas", "share"), [(3, 1, 3), (3, 2, 2), (3, 3, 1), (3, 4, 1), (4, 2, 2)]
)
def test_the_fair_share_is_the_ceiling(offices: int, replicas: int, share: int) -> None:
    assert fair_share(offices, replicas) == share


def test_replicas_try_the_offices_in_different_orders() -> None:
    orders = {tuple(try_order(OFFICES, f"replica-{n}")) for n in range(6)}
    assert len(orders) > 1 and all(sorted(o) == OFFICES for o in orders)


async def test_offices_spread_when_a_replica_joins_and_move_when_it_leaves(
    tmp_path: Path,
) -> None:
    now = [1000.0]
    path = tmp_path / "leases.sqlite3"
    a, b = Replica(path, "a", now), Replica(path, "b", now)
    try:
        await a.balancer.balance()
        assert set(a.running) == set(OFFICES)  # alone: every office
        await b.balancer.balance()  # B joins: nothing free yet
        assert b.running == {}
        await a.balancer.balance()  # A sees two replicas: hands one back
        assert len(a.running) == 2
        await b.balancer.balance()  # and B takes it
        assert len(b.running) == 1 and set(a.running) | set(b.running) == set(OFFICES)
        for _ in range(3):  # stable: nobody takes more than its share
            await a.balancer.balance()
            await b.balancer.balance()
        assert (len(a.running), len(b.running)) == (2, 1)

        # A leaves cleanly: its offices and its heartbeat are released; B takes all.
        for office in list(a.running):
            await a.stop(office)
        await a.balancer.stop()
        await b.balancer.balance()
        assert set(b.running) == set(OFFICES)

        # A returns, then dies without a word: B takes its office back once it expired.
        await a.balancer.balance()
        await b.balancer.balance()
        await a.balancer.balance()
        assert (len(a.running), len(b.running)) == (1, 2)
        now[0] += TTL_S / 2
        await b.balancer.balance()
        assert len(b.running) == 2  # A's lease has not expired yet
        now[0] += TTL_S
        await b.balancer.balance()
        assert set(b.running) == set(OFFICES)
        assert b.balancer.replicas == ["b"]
    finally:
        a.leases.close()
        b.leases.close()
