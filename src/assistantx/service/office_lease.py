"""One replica runs the office at a time: the service holds the office's lease while it runs.

With ``ASSISTANTX_DATABASE_URL`` several ``assistantx serve`` processes (replicas, each with
its own data folder) may share one PostgreSQL database. Before it starts the assistant (and
resumes what the journal holds unfinished), a replica takes the office's lease
(``store.leases``); while another holds it, the replica waits as a standby, trying again every
third of the lease's time. The holder renews the lease every third of its time; every journal
write carries its fencing token (``Journal.hold``), so once the lease is lost (the process was
paused past the expiry, or cut off from the database) nothing it writes lands, and
``on_lost`` is called (the CLI stops the process; a supervisor restarts it as a standby). A
clean shutdown releases the lease, so a standby takes over at once; a killed holder's lease
expires after ``ttl_s``, and the standby resumes its unfinished instructions from the journal.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Callable

from assistantx.core.errors import LeaseLostError
from assistantx.store.journal import Journal
from assistantx.store.leases import Lease, Leases

logger = logging.getLogger(__name__)


class OfficeLease:
    """``await acquire()`` (waits while another replica holds it), ``start()`` renewing,
    ``await stop()`` releasing."""

    def __init__(
        self,
        leases: Leases,
        office: str,
        holder: str,
        ttl_s: float,
        on_lost: Callable[[], None],
    ) -> None:
        self.leases = leases
        self.office = office
        self.holder = holder
        self.ttl_s = ttl_s
        self.on_lost = on_lost
        self.lease: Lease | None = None
        self._renewing: asyncio.Task[None] | None = None

    async def acquire(self) -> Lease:
        """The lease, once this replica gets it; logs once that it waits as a standby."""
        waiting = False
        while True:
            lease = await asyncio.to_thread(
                self.leases.acquire, self.office, self.holder, self.ttl_s
            )
            if lease is not None:
                if waiting:
                    logger.warning("office %s taken over by this replica", self.office)
                self.lease = lease
                return lease
            if not waiting:
                logger.warning(
                    "office %s is run by another replica; waiting as a standby", self.office
                )
                waiting = True
            await asyncio.sleep(self.ttl_s / 3)

    def hold(self, journal: Journal) -> None:
        """Every write of ``journal`` from now on carries this replica's fencing token."""
        journal.hold(self.lease)

    def start(self) -> None:
        if self._renewing is None:
            self._renewing = asyncio.create_task(self._renew(), name="office-lease")

    async def _renew(self) -> None:
        while self.lease is not None:
            await asyncio.sleep(self.ttl_s / 3)
            try:
                self.lease = await asyncio.to_thread(self.leases.renew, self.lease, self.ttl_s)
            except LeaseLostError:
                self.lease = None
            except Exception as exc:  # the database unreachable: retried until the expiry
                logger.warning("office %s: cannot renew the lease (%s)", self.office, exc)
        logger.error("office %s: this replica lost its lease; stopping", self.office)
        self.on_lost()

    async def stop(self) -> None:
        """Stop renewing and hand the office over (idempotent)."""
        if self._renewing is not None:
            self._renewing.cancel()
            try:
                await self._renewing
            except asyncio.CancelledError:
                pass
            self._renewing = None
        lease, self.lease = self.lease, None
        if lease is not None:
            await asyncio.to_thread(self.leases.release, lease)
