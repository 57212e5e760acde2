"""One replica runs the office at a time: the service holds the office's lease while it runs.

With ``ASSISTANTX_DATABASE_URL`` several ``assistantx serve`` processes (replicas, each with
its own data folder) may share one PostgreSQL database. Before it starts the assistant (and
resumes what the journal holds unfinished), a replica takes the office's lease
(``store.leases``); while another holds it, the replica waits as a standby, trying again every
third of the lease's time. The holder renews the lease every third of its time (from a thread,
so a busy event loop does not lose it); every journal
write carries its fencing token (``Journal.hold``), so once the lease is lost (the process was
paused past the expiry, or cut off from the database) nothing it writes lands, and
``on_lost`` is called (the CLI stops the process; a supervisor restarts it as a standby). A
clean shutdown releases the lease, so a standby takes over at once; a killed holder's lease
expires after ``ttl_s``, and the standby resumes its unfinished instructions from the journal.
"""

from __future__ import annotations

import asyncio
import logging
import threading
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
        self._renewer: threading.Thread | None = None
        self._stopping = threading.Event()

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
        """Renew from a thread of its own: a start-up or a burst of work that holds the event
        loop for longer than the lease (seen: a takeover's start-up on a loaded machine, 2.6 s
        against a 2 s lease) must not hand the office to a third replica. The lease says the
        process is alive and reaches the database; a paused or killed process renews nothing."""
        if self._renewer is None:
            self._stopping.clear()
            self._renewer = threading.Thread(
                target=self._renew,
                args=(asyncio.get_running_loop(),),
                name="office-lease",
                daemon=True,
            )
            self._renewer.start()

    def _renew(self, loop: asyncio.AbstractEventLoop) -> None:
        while self.lease is not None and not self._stopping.wait(self.ttl_s / 3):
            try:
                self.lease = self.leases.renew(self.lease, self.ttl_s)
            except LeaseLostError:
                self.lease = None
            except Exception as exc:  # the database unreachable: retried until the expiry
                logger.warning("office %s: cannot renew the lease (%s)", self.office, exc)
        if self._stopping.is_set():
            return
        logger.error("office %s: this replica lost its lease; stopping", self.office)
        try:
            loop.call_soon_threadsafe(self.on_lost)
        except RuntimeError:  # the loop already closed: the process is ending anyway
            pass

    async def stop(self) -> None:
        """Stop renewing and hand the office over (idempotent)."""
        if self._renewer is not None:
            self._stopping.set()
            await asyncio.to_thread(self._renewer.join)
            self._renewer = None
        lease, self.lease = self.lease, None
        if lease is not None:
            await asyncio.to_thread(self.leases.release, lease)
