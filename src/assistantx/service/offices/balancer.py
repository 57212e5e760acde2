"""Offices spread over the replicas sharing one database, each under its own lease.

Every replica heartbeats a lease of its own (``replica:ID`` in the leases table, with the
offices' ``ttl_s``): the live replicas are the unexpired ones. Every third of the lease's
time a replica counts them and takes its fair share, ``ceil(offices / replicas)``: below it,
it takes free (or expired) office leases, in an order of its own so that replicas starting
together try different offices first; above it (a replica joined), it hands its surplus back,
one office a round, stopping the office first and releasing its lease last, so the joiner
finds it free at its next round. A replica that leaves cleanly releases its offices and its
heartbeat, and the others take them at their next round; one killed stops renewing, and its
offices move once their leases expire.

Each office a replica holds is renewed by its own ``OfficeLease`` (and fenced by its token),
so the spread only decides which offices to take or hand back; losing one (a pause past the
expiry) stops that office alone.
"""

from __future__ import annotations

import asyncio
import logging
import math
import time
import zlib
from collections.abc import Awaitable, Callable, Coroutine
from typing import Any

from assistantx.store.leases import Lease, Leases

logger = logging.getLogger(__name__)

REPLICA_PREFIX = "replica:"  # a replica's heartbeat row; office ids never hold a ':'


def fair_share(offices: int, replicas: int) -> int:
    """The most offices one replica runs: ``ceil(offices / replicas)`` (at least one
    replica: this one)."""
    return math.ceil(offices / max(replicas, 1))


def try_order(offices: list[str], replica: str) -> list[str]:
    """The offices in this replica's order of trying: rotated by a hash of its id, so that
    replicas starting together do not all race for the same first office."""
    if not offices:
        return []
    start = zlib.crc32(replica.encode()) % len(offices)
    return offices[start:] + offices[:start]


class Balancer:
    """``await start()`` (the first round done: what is free is taken), ``await stop()``;
    ``holders()``: who runs each office, as the last round read it."""

    def __init__(
        self,
        leases: Leases,
        offices: list[str],
        replica: str,
        ttl_s: float,
        *,
        start_office: Callable[[str, Lease], Awaitable[None]],
        stop_office: Callable[[str], Awaitable[None]],
        held: Callable[[], set[str]],
        clock: Callable[[], float] = time.time,
    ) -> None:
        self.leases = leases
        self.offices = list(offices)
        self.replica = replica
        self.ttl_s = ttl_s
        self._start_office = start_office
        self._stop_office = stop_office
        self._held = held
        self._clock = clock
        self._heartbeat: Lease | None = None
        self._holders: dict[str, str] = {}
        self.replicas: list[str] = [replica]
        self.heartbeats: dict[str, float] = {}  # live replica -> when it last heartbeat
        self._loop: asyncio.Task[None] | None = None
        self._beating: asyncio.Task[None] | None = None
        self._tasks: set[asyncio.Task[None]] = set()
        self._failing = False

    async def start(self) -> None:
        await self.balance()
        if self._loop is None:
            self._loop = asyncio.create_task(self._run(), name="office-balancer")
            # Its own task: a round that starts an office may outlast a heartbeat's term.
            self._beating = asyncio.create_task(self._beat(), name="replica-heartbeat")

    async def stop(self) -> None:
        """Stop taking offices and end the heartbeat (the offices themselves are stopped by
        their owner, releasing their leases)."""
        for task in (self._loop, self._beating):
            if task is not None:
                task.cancel()
                try:
                    await task
                except asyncio.CancelledError:
                    pass
        self._loop = self._beating = None
        for task in list(self._tasks):
            await task
        heartbeat, self._heartbeat = self._heartbeat, None
        if heartbeat is not None:
            try:
                await asyncio.to_thread(self.leases.release, heartbeat)
            except Exception as exc:  # the database gone: the heartbeat expires by itself
                logger.warning("replica %s: cannot end its heartbeat (%s)", self.replica, exc)

    def track(self, work: Coroutine[Any, Any, None]) -> None:
        """Run ``work`` (an office stopping) as a task awaited on ``stop``."""
        task = asyncio.create_task(work)
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    def holders(self) -> dict[str, str]:
        return dict(self._holders)

    def heartbeat_ages(self) -> dict[str, float]:
        """Seconds since each live replica last heartbeat, as of the last round."""
        now = self._clock()
        return {replica: max(0.0, now - beat) for replica, beat in self.heartbeats.items()}

    async def _run(self) -> None:
        while True:
            await asyncio.sleep(self.ttl_s / 3)
            try:
                await self.balance()
            except Exception as exc:  # the database unreachable: logged once, retried
                if not self._failing:
                    logger.warning("replica %s: cannot balance offices (%s)", self.replica, exc)
                    self._failing = True
                continue
            if self._failing:
                logger.warning("replica %s: balancing offices again", self.replica)
                self._failing = False

    async def _beat(self) -> None:
        while True:
            await asyncio.sleep(self.ttl_s / 3)
            try:
                await self._heartbeat_now()
            except Exception:  # the database unreachable: the balancing round logs it
                continue

    async def _heartbeat_now(self) -> None:
        self._heartbeat = await asyncio.to_thread(
            self.leases.acquire, REPLICA_PREFIX + self.replica, self.replica, self.ttl_s
        )

    async def balance(self) -> None:
        """One round: heartbeat, count the live replicas, hand back a surplus office or take
        free ones up to the fair share."""
        await self._heartbeat_now()
        rows = await asyncio.to_thread(self.leases.holders)
        now = self._clock()
        live = {
            r.holder
            for r in rows
            if r.office.startswith(REPLICA_PREFIX) and r.holder and r.expires_at > now
        }
        self.replicas = sorted(live | {self.replica})
        # When each live replica last heartbeat (its lease's expiry less its time to live).
        self.heartbeats = {
            r.holder: r.expires_at - self.ttl_s
            for r in rows
            if r.office.startswith(REPLICA_PREFIX) and r.holder and r.expires_at > now
        }
        self._holders = {
            r.office: r.holder
            for r in rows
            if r.office in self.offices and r.holder and r.expires_at > now
        }
        share = fair_share(len(self.offices), len(self.replicas))
        held = self._held()
        if len(held) > share:  # a replica joined: hand one office back
            surplus = max(held)
            logger.info(
                "office %s handed back: %d replicas, %d offices each at most",
                surplus,
                len(self.replicas),
                share,
            )
            await self._stop_office(surplus)
            self._holders.pop(surplus, None)
            return
        for office in try_order(self.offices, self.replica):
            if len(held) >= share:
                break
            if office in held or self._holders.get(office, self.replica) != self.replica:
                continue
            lease = await asyncio.to_thread(self.leases.acquire, office, self.replica, self.ttl_s)
            if lease is None:  # another replica was quicker
                continue
            self._holders[office] = self.replica
            await self._start_office(office, lease)
            held = self._held()
