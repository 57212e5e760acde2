"""The offices of one process: each office's runtime, its tokens, and where each one runs.

One office (no deployment file) is today's service: one ``ServiceRuntime``, its own tokens,
and with a database URL its lease held before it starts. Such a replica answers HTTP from the
start all the same: while another replica holds the office it is a standby that serves health,
``/metrics`` (who holds the office), reads and submissions from the shared journal (as for an
office run elsewhere, below), and its assistant starts once it takes the lease.

Several offices (``ASSISTANTX_OFFICES``) each get their own ``ServiceRuntime`` (own
people, map, robot, lock, messenger, memory and journal: ``deployment``), started and stopped
through an ``AsyncExitStack`` of its own. On SQLite this process runs them all; with a
database URL the ``Balancer`` takes a fair share of the offices' leases and starts the ones it
holds, and the process answers HTTP at once (an office run by another replica answers 503,
naming that replica).

Tokens of several offices are checked here, not by the runtimes (an office run elsewhere has
no runtime here, yet its tokens must still be told from a stranger's): a token of office A
presented to office B gets 403, one line naming both offices.
"""

from __future__ import annotations

import asyncio
import logging
import os
import socket
import time
from collections.abc import Callable
from contextlib import AsyncExitStack
from dataclasses import dataclass
from typing import Any
from uuid import uuid4

from pydantic import SecretStr

from assistantx.core.lifecycle import cancel_and_wait
from assistantx.core.office import load_office
from assistantx.core.settings import Settings
from assistantx.memory.resolve import Resolver
from assistantx.service.auth import (
    Principal,
    TokenAuthority,
    build_authority,
    generated_operator_token,
)
from assistantx.service.datalock import DataDirLock
from assistantx.service.errors import (
    ForbiddenError,
    NotFoundError,
    UnauthorizedError,
    UnavailableError,
)
from assistantx.service.office_lease import OfficeLease
from assistantx.service.offices.balancer import Balancer
from assistantx.service.offices.deployment import OfficeSpec, load_deployment
from assistantx.service.offices.submissions import OfficeDesk
from assistantx.service.runtime import JOURNAL_FILE, ServiceRuntime
from assistantx.store.journal import Journal
from assistantx.store.leases import Lease, Leases

logger = logging.getLogger(__name__)

STARTING, READY, ELSEWHERE, UNASSIGNED = "starting", "ready", "elsewhere", "unassigned"


@dataclass(frozen=True)
class ReplicaView:
    """One replica as this one sees it through the shared leases."""

    id: str
    here: bool  # the replica answering
    up: bool  # its heartbeat (or, one office, its lease) is live
    heartbeat_age_s: float | None  # seconds since its last heartbeat (several offices only)
    offices: list[str]  # the ids of the offices it runs


@dataclass
class OfficeSlot:
    """One office of the deployment and, while this process runs it, its runtime."""

    spec: OfficeSpec
    authority: TokenAuthority | None = None  # several offices: built at start
    runtime: ServiceRuntime | None = None
    stack: AsyncExitStack | None = None
    lease: OfficeLease | None = None
    display: str = ""  # the office's name as people read it
    desk: OfficeDesk | None = None  # run elsewhere: its journal, for reads and submissions


class Offices:
    """``await start(stack)``; ``runtime(office)``, ``authenticate(office, header)``,
    ``listing()``; everything stops with the stack."""

    def __init__(
        self,
        settings: Settings,
        data_lock: DataDirLock | None = None,
        on_lease_lost: Callable[[], None] | None = None,
    ) -> None:
        self.settings = settings
        self.specs = load_deployment(settings)
        self.several = settings.offices is not None
        self.data_lock = data_lock
        self.on_lease_lost = on_lease_lost
        self.replica = settings.replica_id or (
            f"{socket.gethostname()}-{os.getpid()}-{uuid4().hex[:6]}"
        )
        self.slots = {spec.id: OfficeSlot(spec) for spec in self.specs}
        self.home = self.specs[0].id
        self.leases: Leases | None = None
        self.balancer: Balancer | None = None
        self.started = False
        self.standing_by = False  # one office on replicas: until its assistant first runs here
        # Called with an office's id and runtime each time it starts running here, at start-up
        # or later (the balancer took it over): the app routes its Matrix pushes to it.
        self.on_started: Callable[[str, ServiceRuntime], None] | None = None
        self.generated_token: str | None = None  # the deployment operator's, when generated
        self._deployment_operator = ""
        if not self.several:  # today's service: its runtime exists before it starts
            runtime = ServiceRuntime(settings, data_lock)
            runtime.on_lease_lost = on_lease_lost  # replicas: another took the office over
            self.slots[self.home].runtime = runtime

    # -- start and stop ---------------------------------------------------------------------
    async def start(self, stack: AsyncExitStack) -> None:
        stack.callback(self._not_started)
        if not self.several:
            runtime = self.slots[self.home].runtime
            assert runtime is not None
            if self.settings.database is not None:
                await self._start_standby(stack, runtime, self.settings.database)
                return
            await runtime.start(stack)
            self.slots[self.home].display = runtime.office.name
            self._started(self.home, runtime)
            self.started = True
            return
        await asyncio.to_thread(self._build_authorities)
        url = self.settings.database
        if url is None:  # one process runs every office
            stack.push_async_callback(self._stop_all)  # also those started before one failed
            for office_id in self.slots:
                await self._start_office(office_id, None)
            self.started = True
            return
        await asyncio.to_thread(_create_schemas, url, self.specs)
        self.leases = Leases.open(self.settings.data_dir / JOURNAL_FILE, database_url=url)
        stack.callback(self.leases.close)  # last: the offices release their leases through it
        stack.push_async_callback(self._stop_all)
        stack.callback(self._close_desks)
        self.balancer = Balancer(
            self.leases,
            list(self.slots),
            self.replica,
            self.settings.lease_ttl_s,
            start_office=self._start_office,
            stop_office=self._stop_office,
            held=lambda: {o for o, slot in self.slots.items() if slot.stack is not None},
        )
        stack.push_async_callback(self.balancer.stop)  # first: no office is taken meanwhile
        await self.balancer.start()
        self.started = True

    def _not_started(self) -> None:
        self.started = False

    async def _start_standby(
        self, stack: AsyncExitStack, runtime: ServiceRuntime, url: str
    ) -> None:
        """One office on replicas: serve at once, and start the assistant in the background
        once this replica holds the office's lease (``ServiceRuntime.start`` waits for it).
        The tokens are checked here meanwhile; the shared leases say who holds the office."""
        await asyncio.to_thread(self._build_authorities)
        self.leases = Leases.open(self.settings.data_dir / JOURNAL_FILE, database_url=url)
        stack.callback(self.leases.close)
        stack.callback(self._close_desks)
        runtime.listen_as = self.home  # submissions journaled by a standby reach it
        own = AsyncExitStack()  # the runtime's: closed after its start is cancelled

        async def run() -> None:
            try:
                await runtime.start(own)
                self.standing_by = False  # from now on it answers as the holder, or not at all
                self._started(self.home, runtime)
            except Exception:
                logger.exception("the office could not start on this replica")
                if self.on_lease_lost is not None:
                    self.on_lease_lost()  # the CLI stops the process, as on a lost lease

        self.standing_by = True
        task = asyncio.create_task(run(), name="office-start")

        async def stop() -> None:
            await cancel_and_wait(task)
            await own.aclose()

        stack.push_async_callback(stop)
        self.started = True

    def _build_authorities(self) -> None:
        base = self.settings
        deployment_operator = (
            base.operator_token.get_secret_value()
            if base.operator_token is not None
            else generated_operator_token(base.data_dir)
        )
        if base.operator_token is None:
            self.generated_token = deployment_operator
        self._deployment_operator = deployment_operator
        for slot in self.slots.values():
            s = slot.spec.settings
            office = load_office(s.office)
            slot.display = slot.spec.name or office.name
            setup = build_authority(
                deployment_operator,
                s.tokens.get_secret_value() if s.tokens is not None else None,
                Resolver(office),
                s.data_dir,
            )
            if slot.spec.operator_token is not None:
                setup.authority.add(slot.spec.operator_token, Principal(person=None))
            slot.authority = setup.authority

    async def _start_office(self, office_id: str, lease: Lease | None) -> None:
        """Start ``office_id``'s runtime (under ``lease`` when replicas share a database);
        a failure is logged and leaves the office to the next try (or another replica)."""
        slot = self.slots[office_id]
        spec = slot.spec
        # The runtime's own authority is not asked (``authenticate`` is); given the
        # deployment operator's token, it generates none of its own.
        settings = spec.settings.model_copy(
            update={"operator_token": SecretStr(self._deployment_operator)}
        )
        runtime = ServiceRuntime(settings, self.data_lock if spec.home else None)
        runtime.office_id = office_id
        stack = AsyncExitStack()
        try:
            if lease is not None:
                assert self.leases is not None
                holder = OfficeLease(
                    self.leases,
                    office_id,
                    self.replica,
                    self.settings.lease_ttl_s,
                    lambda: self._lease_lost(office_id),
                )
                holder.lease = lease
                stack.push_async_callback(holder.stop)  # the last step: hands the office over
                holder.start()
                runtime.office_lease = holder
                slot.lease = holder
            slot.stack, slot.runtime = stack, runtime
            await runtime.start(stack)
        except Exception:
            logger.exception("office %s could not start", office_id)
            await self._stop_office(office_id)
            if lease is None:
                raise  # one process runs every office: a bad office stops the start-up
            return
        self._started(office_id, runtime)
        logger.info("office %s runs on this replica (%s)", office_id, self.replica)

    def _started(self, office_id: str, runtime: ServiceRuntime) -> None:
        if self.on_started is not None:
            self.on_started(office_id, runtime)

    async def _stop_office(self, office_id: str) -> None:
        slot = self.slots[office_id]
        stack, slot.stack = slot.stack, None
        if stack is None:
            return
        if slot.runtime is not None:
            slot.runtime.ready = False
            slot.runtime.hub.close()
        try:
            await stack.aclose()
        finally:
            slot.runtime, slot.lease = None, None
        logger.info("office %s stopped on this replica (%s)", office_id, self.replica)

    def _lease_lost(self, office_id: str) -> None:
        """Another replica took ``office_id``: only that office stops here."""
        if self.balancer is not None:
            self.balancer.track(self._stop_office(office_id))

    async def _stop_all(self) -> None:
        for office_id in reversed(list(self.slots)):
            await self._stop_office(office_id)

    # -- requests ---------------------------------------------------------------------------
    def slot(self, office_id: str | None) -> OfficeSlot:
        slot = self.slots.get(office_id or self.home)
        if slot is None:
            raise NotFoundError(f"no office {office_id!r}")
        return slot

    def serving(self, office_id: str | None) -> ServiceRuntime | None:
        """The runtime of ``office_id`` while it runs here; None otherwise (no error)."""
        slot = self.slots.get(office_id or self.home)
        runtime = slot.runtime if slot is not None else None
        return runtime if runtime is not None and runtime.ready else None

    def runtime(self, office_id: str | None) -> ServiceRuntime:
        """The runtime answering for ``office_id`` (None: the home office); 503 while it
        starts or stops, or when another replica runs it."""
        slot = self.slot(office_id)
        runtime = slot.runtime
        if runtime is not None and runtime.ready:
            return runtime
        holder = self.holder(slot.spec.id)
        if self.several and holder is not None and holder != self.replica:
            raise UnavailableError(f"the office {slot.display} is run by replica {holder}")
        raise UnavailableError("the assistant is starting or stopping; try again shortly")

    async def desk(self, office_id: str | None) -> ServiceRuntime | OfficeDesk:
        """What answers instruction reads and submissions for ``office_id``: its runtime when
        it runs here; on a shared database, else the office's journal there
        (``submissions``); otherwise the 503 of ``runtime``."""
        slot = self.slot(office_id)
        runtime = slot.runtime
        url = slot.spec.settings.database
        # One office: only a standby (a holder that lost its lease is stopping: 503).
        elsewhere = self.several or self.standing_by
        if (runtime is not None and runtime.ready) or url is None or not elsewhere:
            return self.runtime(office_id)
        if slot.desk is None:
            journal = await asyncio.to_thread(
                Journal.open, slot.spec.settings.data_dir / JOURNAL_FILE, database_url=url
            )
            office = await asyncio.to_thread(load_office, slot.spec.settings.office)
            if slot.desk is None:
                slot.desk = OfficeDesk(slot.spec.id, office, journal)
            else:  # opened meanwhile by another request
                journal.close()
        return slot.desk

    def _close_desks(self) -> None:
        for slot in self.slots.values():
            if slot.desk is not None:
                slot.desk.close()
                slot.desk = None

    def authenticate(self, office_id: str | None, authorization: str | None) -> Principal:
        slot = self.slot(office_id)
        if not self.several:
            running = self.serving(office_id)
            if running is None and slot.authority is not None:  # a standby's
                return slot.authority.authenticate(authorization)
            return self.runtime(office_id).auth.authority.authenticate(authorization)
        assert slot.authority is not None
        try:
            return slot.authority.authenticate(authorization)
        except UnauthorizedError:
            for other in self.slots.values():
                if other is slot or other.authority is None:
                    continue
                try:
                    other.authority.authenticate(authorization)
                except UnauthorizedError:
                    continue
                raise ForbiddenError(
                    f"this token is for the office {other.display}, not {slot.display}"
                ) from None
            raise

    def offices_of(self, authorization: str | None) -> list[OfficeSlot]:
        """The offices a token holds for; UnauthorizedError when it holds for none."""
        found: list[OfficeSlot] = []
        for slot in self.slots.values():
            try:
                self.authenticate(slot.spec.id, authorization)
            except (UnauthorizedError, ForbiddenError, UnavailableError):
                continue
            found.append(slot)
        if not found:
            self.authenticate(self.home, authorization)  # raises the usual 401 (or 503)
        return found

    def holder(self, office_id: str) -> str | None:
        """The replica running ``office_id``: this one, another (from the shared leases), or
        None."""
        slot = self.slots[office_id]
        if not self.several and slot.runtime is not None:
            lease = slot.runtime.office_lease  # replicas of one office: the lease's holder
            if lease is not None and lease.lease is not None:
                return lease.holder
            if self.leases is not None:  # a standby: whoever the shared lease names
                return self._lease_holder(slot.display)
            return lease.holder if lease is not None else self.replica
        if slot.stack is not None:
            return self.replica
        if self.balancer is not None:
            return self.balancer.holders().get(office_id)
        return None

    def _lease_holder(self, office_name: str) -> str | None:
        """The replica whose unexpired lease holds the office (one office on replicas)."""
        assert self.leases is not None
        now = time.time()
        for lease in self.leases.holders():
            if lease.office == office_name and lease.holder and lease.expires_at > now:
                return lease.holder
        return None

    def runs_here(self, office_id: str) -> bool:
        """Whether this process runs ``office_id`` (ready or still starting; a standby of
        one office waiting for its lease does not)."""
        slot = self.slots[office_id]
        if self.several:
            return slot.stack is not None
        if slot.runtime is None:
            return False
        lease = slot.runtime.office_lease
        return self.leases is None or (lease is not None and lease.lease is not None)

    def status(self, office_id: str) -> str:
        slot = self.slots[office_id]
        if slot.runtime is not None and slot.runtime.ready:
            return READY
        if self.runs_here(office_id):
            return STARTING
        return UNASSIGNED if self.holder(office_id) is None else ELSEWHERE

    def listing(self, slots: list[OfficeSlot]) -> list[dict[str, Any]]:
        return [
            {
                "id": slot.spec.id,
                "name": slot.display,
                "replica": self.holder(slot.spec.id),
                "here": self.runs_here(slot.spec.id),
                "status": self.status(slot.spec.id),
            }
            for slot in slots
        ]

    def replicas(self) -> list[ReplicaView]:
        """Every replica this one knows of, with its health and the offices it runs: the
        live ones (heartbeats; one office: this replica and the holder of the unexpired
        lease) and any that still hold an office's lease without a live heartbeat (down).
        Without a database, this process alone."""
        runs: dict[str, list[str]] = {}
        for office in self.slots:
            holder = self.holder(office)
            if holder is not None:
                runs.setdefault(holder, []).append(office)
        balancer = self.balancer
        live = set(balancer.replicas) if balancer is not None else {self.replica, *runs}
        ages = balancer.heartbeat_ages() if balancer is not None else {}
        return [
            ReplicaView(
                id=replica,
                here=replica == self.replica,
                up=replica in live,
                heartbeat_age_s=ages.get(replica),
                offices=runs.get(replica, []),
            )
            for replica in sorted(live | set(runs))
        ]

    def running(self) -> list[ServiceRuntime]:
        return [s.runtime for s in self.slots.values() if s.runtime is not None]

    def close_streams(self) -> None:
        """Every office's live streams end (the server is stopping)."""
        for runtime in self.running():
            runtime.hub.close()


def _create_schemas(url: str, specs: list[OfficeSpec]) -> None:
    """Each office's schema, before its stores migrate in it (replicas racing are fine)."""
    import psycopg  # PostgreSQL only: on SQLite a start never loads it (~0.15 CPU-s)

    with psycopg.connect(url, autocommit=True) as db:
        for spec in specs:
            if spec.schema is None:
                continue
            try:
                db.execute(f'CREATE SCHEMA IF NOT EXISTS "{spec.schema}"')
            except psycopg.errors.UniqueViolation:
                pass  # another replica created it at the same moment
