"""The service's composition: office, journal, adapters, the Assistant, auth and metrics.

``ServiceRuntime.start`` builds everything from the settings and enters each adapter through
the caller's ``AsyncExitStack`` (the app lifespan), so they stop in reverse order. Embedded
defaults: the default office, the navigator robot base (map, planner, AMCL) in simulation,
the in-process lock, the built-in messenger, simulated colleagues, the embedded reasoner, all
on a sped-up WallClock. ``ASSISTANTX_ROBOT=sim`` swaps in the kinematic base,
``ASSISTANTX_LOCK=tcp`` the locker behind ``assistantx lock-sim`` (or a real one).
"""

from __future__ import annotations

import asyncio
import logging
import os
import socket
from collections.abc import Callable
from contextlib import AsyncExitStack
from pathlib import Path
from typing import TYPE_CHECKING, Any
from uuid import uuid4

from assistantx.adapters.lock.protocol.keys import LockKeys, load_lock_keys
from assistantx.adapters.lock.tcp import TcpLocker
from assistantx.adapters.messenger.builtin import BuiltinMessenger
from assistantx.adapters.model import model_from_settings
from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
from assistantx.agents.base import ReasonerFactory
from assistantx.agents.registry import load_builder, needs_llm, reasoner_factory
from assistantx.core.clock import WallClock
from assistantx.core.errors import LockConnectionError
from assistantx.core.office import Office, PersonId, load_office
from assistantx.core.ports.lock import Locker
from assistantx.core.ports.messenger import ChatRef, InboundMessage, OutboundMessage
from assistantx.core.ports.robot import RobotBase
from assistantx.core.settings import Settings
from assistantx.memory.resolve import Resolver
from assistantx.nav import disk_cache
from assistantx.runtime.assistant import (
    Assistant,
    AssistantParts,
    new_instruction_id,
)
from assistantx.runtime.loop import LoopLimits
from assistantx.service import colleagues, fleet_wiring
from assistantx.service.admission import Admission
from assistantx.service.auth import AuthSetup, build_authority
from assistantx.service.code_ledger import CodeLedger
from assistantx.service.code_recovery import settle_codes
from assistantx.service.codebook import CodeBook
from assistantx.service.data_dir import LOCK_KEYS_FILE, ensure_data_dir
from assistantx.service.datalock import DataDirLock
from assistantx.service.durability import Durability
from assistantx.service.errors import (
    TooManyRequestsError,
    journaled_instruction,
    unknown_instruction,
)
from assistantx.service.feedback_wiring import start_feedback
from assistantx.service.heap_trim import HeapTrim, malloc_trim
from assistantx.service.hub import EventHub
from assistantx.service.loop_lag import LoopLagMonitor
from assistantx.service.office_lease import OfficeLease
from assistantx.service.offices.deployment import claim_journal
from assistantx.service.offices.submissions import SubmissionListener
from assistantx.service.rate_limit import InstructionRate, refusal_text
from assistantx.service.reasoner_warmup import DEFERRED_REASONERS, DeferredFactory
from assistantx.service.retention import Retention
from assistantx.service.robots import RobotGauges, robot_states
from assistantx.service.shared_phones import SharedPhones
from assistantx.service.telemetry import ServiceMetrics
from assistantx.service.turns import turns_of
from assistantx.sim.fleet import SimFleet
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.office import SimOffice
from assistantx.store.journal import InstructionRecord, Journal
from assistantx.store.leases import Leases, fence

if TYPE_CHECKING:  # Matrix loads when the settings ask for it (httpx and the rest: ~0.2 CPU-s)
    from assistantx.adapters.messenger.matrix import MatrixRuntime, MatrixSetup
    from assistantx.agents.symbolic.requests import RequestRecognizer

logger = logging.getLogger(__name__)

JOURNAL_FILE = "journal.sqlite3"
MAP_CACHE_DIR = "map-cache"  # arrays derived from the map (nav.disk_cache)
SIM_CODES_FILE = "sim-codes.json"  # simulated people's QR payloads: credentials, not journaled
CODEBOOK_FILE = "locker-codes.json"  # every QR payload sent and not expired, for the dashboard


class ServiceRuntime:
    """Everything a request handler needs, built once per app."""

    office: Office
    resolver: Resolver
    journal: Journal
    clock: WallClock
    sim: SimOffice
    locker: Locker
    lock_keys: LockKeys
    phones: colleagues.CodePhones | SharedPhones
    codebook: CodeBook
    ledger: CodeLedger
    messenger: BuiltinMessenger
    assistant: Assistant
    durability: Durability
    auth: AuthSetup
    metrics: ServiceMetrics
    admission: Admission

    def __init__(self, settings: Settings, data_lock: DataDirLock | None = None) -> None:
        """``data_lock``: the data folder's lock when the caller took it already (the CLI takes
        it before binding its port); else ``start`` takes it."""
        self.settings = settings
        self.data_lock = data_lock
        self.hub = EventHub()
        self.loop_lag = LoopLagMonitor()
        self.ready = False
        self.resumed: list[str] = []
        self.office_lease: OfficeLease | None = None  # with a database URL: the office's lease
        self.office_id: str | None = None  # one of several offices: its id in the deployment
        # On a shared database: the office id other replicas NOTIFY submissions under (one
        # office on replicas: its standbys take submissions too); None: ``office_id``.
        self.listen_as: str | None = None
        self._picked_up: set[str] = set()  # submissions journaled by other replicas, admitted
        self.on_lease_lost: Callable[[], None] | None = None  # the CLI stops the process
        # ASSISTANTX_MESSENGER=matrix: the assistant talks on Matrix. Its config is checked
        # here (create_app fails fast on a bad one); it is built in start, with the rest.
        self.matrix_setup: MatrixSetup | None = None
        if settings.messenger == "matrix":
            from assistantx.adapters.messenger.matrix import matrix_setup

            self.matrix_setup = matrix_setup(settings)
        self.matrix: MatrixRuntime | None = None
        self.fleet: SimFleet | None = None  # ASSISTANTX_ROBOTS > 1 (service.fleet_wiring)
        self._deferred_reasoner: DeferredFactory | None = None  # built after ready
        fleet_wiring.check_fleet_settings(settings)

    # -- start-up ------------------------------------------------------------------------
    async def start(self, stack: AsyncExitStack) -> None:
        s = self.settings
        self.office = load_office(s.office)
        self.resolver = Resolver(self.office)
        data_dir = ensure_data_dir(s.data_dir)
        if self.data_lock is None or not self.data_lock.held:
            self.data_lock = DataDirLock(data_dir).acquire()  # DataDirBusyError: another serves
            stack.callback(self.data_lock.release)
        if s.database is not None and self.office_lease is None:
            # Replicas share the database: run only under the lease (several offices: the
            # caller took this office's lease and set ``office_lease`` already).
            await self._hold_office(stack, data_dir, s.database)
        self.journal = Journal.open(data_dir / JOURNAL_FILE, database_url=s.database)
        stack.callback(self.journal.close)  # before the lease's release: its last writes land
        if self.office_lease is not None:
            self.office_lease.hold(self.journal)
        if self.office_id is not None:  # one of several offices: this journal must be its own
            if s.database:
                from assistantx.store.postgres_store import redact  # psycopg: PostgreSQL only

                where = redact(s.database)
            else:
                where = str(data_dir / JOURNAL_FILE)
            claim_journal(self.journal, self.office_id, where)
        # The map's distance transforms, kept by content hash: a second start reads them.
        disk_cache.use_directory(data_dir / MAP_CACHE_DIR)
        stack.callback(disk_cache.use_directory, None)
        self.metrics = ServiceMetrics(self.journal)
        self.metrics.watch_loop(self.loop_lag)
        self.metrics.watch_streams(lambda: len(self.hub))
        if self.office_lease is not None:
            office_lease = self.office_lease
            self.metrics.watch_lease(lambda: office_lease.lease, lambda: self.ready)
        self.auth = build_authority(
            s.operator_token.get_secret_value() if s.operator_token else None,
            s.tokens.get_secret_value() if s.tokens else None,
            self.resolver,
            data_dir,
        )
        # Timestamps are real time; the speed-up shortens simulated durations only.
        self.clock = WallClock(s.effective_speedup)
        self.lock_keys = lock_keys_for(s, data_dir)
        if s.database is None:
            self.phones = colleagues.CodePhones(data_dir / SIM_CODES_FILE)
        else:  # replicas: the simulated people keep their codes across a takeover
            self.phones = shared = SharedPhones.open(s.database)
            stack.callback(shared.close)
            if self.office_lease is not None and self.office_lease.lease is not None:
                shared.fence = fence(self.office_lease.lease, postgres=True)
        self.locker = self._locker()
        world = self.journal.state(colleagues.SIM_STATE)
        robot_place = world["robot"]["place"] if world else None
        unavailable = [self.resolver.person(p) for p in s.sim_unavailable.split(",") if p.strip()]
        self.sim = SimOffice(
            self.office,
            unavailable=unavailable,
            clock=self.clock,
            reply_delay_s=s.sim_reply_delay_s,
            handover_delay_s=s.sim_handover_delay_s,
            locker=self.locker,
            robot=await asyncio.to_thread(self._robot_base, robot_place),
        )
        if s.robots > 1:
            self._join_fleet()
        self.messenger = BuiltinMessenger(self.journal, self.clock)
        self.metrics.skipped_sends = lambda: self.messenger.duplicates_skipped
        # Registered before anything is sent: every code is scannable from the dashboard,
        # also one sent before the page's first request, and after a restart.
        self.codebook = CodeBook(self.lock_keys.codes, self.clock, data_dir / CODEBOOK_FILE)
        self.messenger.relay_to(self.codebook.note)
        if self.matrix_setup is not None:  # Matrix traffic journaled; its codes scannable too
            from assistantx.service.matrix_wiring import build_matrix

            self.matrix = build_matrix(
                stack, self.matrix_setup, transcript=self.journal, relay=self.codebook.note
            )
        inbox = (
            colleagues.connect_colleagues(self.sim, self.messenger)
            if s.people == "simulated"
            else None
        )
        code_lifetime_s = s.lock_code_expiry_min * 60
        self.ledger = CodeLedger(
            self.journal,
            self.clock,
            code_lifetime_s,
            transcript_after_send=self.matrix is not None,
        )
        self.locker.listen(self.ledger.on_lock_event)
        self._request_check: RequestRecognizer | None = None  # made on the first message
        ltm = Durability.restore_memory(self.journal, self.office)
        factory, name = self._reasoner()
        self.assistant = Assistant(
            AssistantParts(
                office=self.office,
                messenger=self.matrix.messenger if self.matrix else self.messenger,
                robot=self.fleet.robot if self.fleet else self.sim.robot,
                locker=self.locker,
                clock=self.clock,
                reasoner_factory=factory,
                reasoner_name=name,
                ltm=ltm,
                limits=LoopLimits(
                    max_steps=s.max_steps,
                    deadline_s=s.instruction_deadline_s,
                    wall_s=s.instruction_wall_s,
                ),
                # A direct message starts an instruction only when it asks for something.
                is_request=self._is_request,
                retire_codes=self.ledger.retire,
                code_records=self.ledger,
                fleet=self.fleet.lease if self.fleet else None,
            )
        )
        self.durability = Durability(
            self.journal, self.assistant, self.hub, self.metrics, self._world_state
        )
        self.durability.attach()
        # After it journaled the event: an instruction waits its turn behind the requests.
        turns = turns_of()
        self.assistant.subscribe(turns.take_after)
        skipped = [self.assistant.skipped]
        if self.matrix is not None:
            skipped.append(self.matrix.messenger.skipped_events)
        self.metrics.count_skipped(*skipped)
        self.metrics.registry.register(RobotGauges(lambda: robot_states(self)))
        deferred = self._deferred_reasoner
        if deferred is not None:  # a direct message's instruction waits off the loop too
            self.assistant.reasoner_ready = deferred.built
        self.admission = Admission(
            self.assistant,
            self.journal,
            deferred.built if deferred is not None else None,
            turn=turns.take,
        )
        self.rate = InstructionRate(s.instructions_per_minute)
        self.assistant.intercept_direct_messages(self._over_the_rate)
        self.assistant.on_instruction_start(self._register_with_sim)
        self.assistant.on_instruction_end(self._end_with_sim)
        # glibc keeps the pages the process freed: they go back every so many instructions.
        self.heap_trim = HeapTrim(malloc_trim())
        self.assistant.on_instruction_end(self.heap_trim.on_end)

        try:
            await stack.enter_async_context(self.locker)
        except LockConnectionError as exc:
            raise LockConnectionError(
                f"{exc}. Start `assistantx lock-sim` first: with no key configured it shares "
                f"the key in {self.settings.data_dir}; otherwise give both the same "
                "ASSISTANTX_LOCK_SHARED_KEY or ASSISTANTX_LOCK_KEY_FILE"
            ) from exc
        # Before anything else restarts: no code the journal says is finished opens again.
        phones = self.phones.load()
        held = colleagues.held_payloads(world, phones) if world is not None else []
        settled = await settle_codes(
            self.journal,
            self.ledger,
            self.locker,
            self.lock_keys.codes,
            [*self.codebook.payloads(), *held],
            self.clock.now(),
            code_lifetime_s,
        )
        for code_id, state in self.ledger.reported().items():
            self.locker.report_code(code_id, state)
        await stack.enter_async_context(self.messenger)
        if inbox is not None:  # stops after the simulator: what they wrote is journaled
            await stack.enter_async_context(inbox)
        await stack.enter_async_context(self.sim.robot)
        if self.fleet is not None:
            await stack.enter_async_context(self.fleet.robot)  # robots 2..
            stack.push_async_callback(self.fleet.lease.stop)  # parking drives
        stack.push_async_callback(self.sim.aclose)  # after the assistant stopped
        if world is not None:
            colleagues.restore(self.sim, world, phones, settled.live)
        self.ledger.world_state = self._world_state  # the world as restored, from now on
        await self.assistant.start()
        if self.matrix is not None:  # started once the assistant's inbox is connected
            from assistantx.service.matrix_wiring import start_matrix

            await start_matrix(stack, self.matrix, self.assistant)
        # Before anything resumes: a resumed instruction is surveyed like a new one. Opened
        # before _stop is pushed, so it closes after the assistant stopped: an instruction
        # that ends during the stop still records its survey (it hit a closed store).
        self.feedback = await start_feedback(
            stack,
            assistant=self.assistant,
            journal_file=data_dir / JOURNAL_FILE,
            database_url=s.database,
            map_yaml=self.map_yaml,
            anchors_yaml=s.map_anchors,
        )
        stack.push_async_callback(self._stop)
        self.loop_lag.start()
        stack.push_async_callback(self.loop_lag.stop)
        self.retention = Retention(self.journal, s.journal_retention_days)
        self.retention.start()
        stack.push_async_callback(self.retention.stop)
        await self._resume()
        await self.durability.resume_give_backs(set(self.sim.world.locker_contents()))
        self.admission.start()
        listen_as = self.listen_as or self.office_id
        if s.database is not None and listen_as is not None:
            await self._listen_for_submissions(stack, s.database, listen_as)
        self.ready = True
        if self._deferred_reasoner is not None:
            self._deferred_reasoner.warm_in_background()

    async def _hold_office(self, stack: AsyncExitStack, data_dir: Path, url: str) -> None:
        s = self.settings
        if s.lock_shared_key is None and s.lock_key_file is None:
            # Each replica would make its own key in its data folder: a code one replica
            # sent before it died would not open the locker under the next one.
            logger.warning(
                "replicas need one lock key: set ASSISTANTX_LOCK_SHARED_KEY (or "
                "ASSISTANTX_LOCK_KEY_FILE) alike on every replica"
            )
        leases = Leases.open(data_dir / JOURNAL_FILE, database_url=url)
        stack.callback(leases.close)
        holder = (
            self.settings.replica_id or f"{socket.gethostname()}-{os.getpid()}-{uuid4().hex[:6]}"
        )
        self.office_lease = OfficeLease(
            leases, self.office.name, holder, self.settings.lease_ttl_s, self._lease_lost
        )
        await self.office_lease.acquire()
        stack.push_async_callback(self.office_lease.stop)  # hands the office over
        self.office_lease.start()

    async def _listen_for_submissions(
        self, stack: AsyncExitStack, url: str, office_id: str
    ) -> None:
        """Start what other replicas journal for this office: told through LISTEN/NOTIFY, and,
        once listening, what they journaled since ``_resume`` read the journal."""
        listener = SubmissionListener(url, office_id, self._pick_up_submitted)
        await listener.start()
        stack.push_async_callback(listener.stop)
        for record in self.journal.unfinished():
            if record.stm is None:
                self._pick_up_submitted(record.id)

    def _pick_up_submitted(self, instruction_id: str) -> None:
        """Admit an instruction another replica journaled, once."""
        if instruction_id in self.resumed or instruction_id in self._picked_up:
            return
        record = self.journal.instruction(instruction_id)
        if record is None or record.status != "queued" or record.stm is not None:
            return
        self._picked_up.add(instruction_id)
        logger.info("instruction %s was submitted through another replica", instruction_id)
        self.admission.admit(record)

    def _lease_lost(self) -> None:
        self.ready = False
        if self.on_lease_lost is not None:
            self.on_lease_lost()

    def _reasoner(self) -> tuple[ReasonerFactory, str]:
        s = self.settings
        if s.reasoner_builder:
            factory = load_builder(s.reasoner_builder)(self.office, s)
            return factory, s.reasoner_builder.partition(":")[2]
        kind = s.effective_reasoner
        if needs_llm(kind) or kind not in DEFERRED_REASONERS:
            model = model_from_settings(s) if needs_llm(kind) else None
            return reasoner_factory(kind, self.office, s, model=model), kind
        # Nothing to check at start (no model, no plug-in): built once the service is ready.
        office = self.office
        self._deferred_reasoner = DeferredFactory(lambda: reasoner_factory(kind, office, s))
        return self._deferred_reasoner, kind

    @property
    def map_yaml(self) -> Path:
        return self.settings.map or DEFAULT_MAP

    def _robot_base(self, place: str | None) -> RobotBase | None:
        """The navigator standing where the journaled world left the robot; None: the
        simulator's kinematic base."""
        s = self.settings
        if s.robot == "sim":
            return None
        if s.robots > 1:
            return fleet_wiring.first_robot(s, self.office, self.clock, place)
        return NavigatorRobot.from_files(
            self.office,
            self.clock,
            map_yaml=self.map_yaml,
            anchors_yaml=s.map_anchors,
            localize=s.robot_localize,
            start=place,
            search_off_loop=True,
        )

    def _join_fleet(self) -> None:
        """Robots 2.. join robot 1; from here on the assistant, the ledger and the code
        book see the fleet's locker (every robot's)."""
        first = self.sim.robot.base
        assert isinstance(first, NavigatorRobot)
        self.fleet = fleet_wiring.join_robots(
            self.settings, self.sim, first, self.lock_keys, self.clock
        )
        self.locker = self.fleet.locker

    def _locker(self) -> Locker:
        s = self.settings
        expiry_s = s.lock_code_expiry_min * 60
        if s.lock == "tcp":
            # Without a configured key both ends use the data folder's key file:
            # `assistantx lock-sim` on the same ASSISTANTX_DATA_DIR reads the same file.
            # The lock checks a code's times on its own (real) clock, so codes are stamped in
            # real time, not in the sped-up simulated time.
            return TcpLocker(
                s.lock_host,
                s.lock_port,
                self.lock_keys,
                lock_id=s.lock_id,
                clock=WallClock(),
                expiry_s=expiry_s,
                render_png=self._sends_images,
            )
        controller = LockController(s.lock_id, self.lock_keys.codes, self.clock)
        return LocalLocker(
            controller, clock=self.clock, expiry_s=expiry_s, render_png=self._sends_images
        )

    @property
    def _sends_images(self) -> bool:
        """QR codes are rendered only where the messenger delivers images (Matrix); the
        built-in messenger carries the code's payload, and the web page draws it."""
        return self.matrix_setup is not None

    def _world_state(self) -> dict[str, dict[str, Any]]:
        self.phones.save(self.sim.codes)  # before the snapshot that names them
        return {colleagues.SIM_STATE: colleagues.snapshot(self.sim)}

    async def _register_with_sim(self, stm: Any) -> None:
        self.sim.register_instruction(stm.instruction_id, stm.requester)

    async def _end_with_sim(self, stm: Any) -> None:
        self.sim.end_instruction(stm.instruction_id)

    async def _resume(self) -> None:
        for record in self.journal.unfinished():
            requester = PersonId(record.requester)  # journaled as resolved at admission
            if record.stm is None:  # journaled, acknowledged, never started
                await self.assistant.submit(requester, record.text, instruction_id=record.id)
            else:
                stm = self.durability.prepare_resume(record)
                await self.assistant.submit(requester, record.text, resume=stm)
                if self.settings.people == "simulated":
                    colleagues.reask_unanswered(self.sim, self.journal, record.id)
            self.resumed.append(record.id)
            logger.info("resumed instruction %s", record.id)
            if record.cancel_requested:
                await self.cancel(record.id)

    async def _stop(self) -> None:
        """Shut down without ending running instructions: they resume on the next start."""
        self.ready = False
        await self.admission.stop()  # what it had not started is journaled as queued
        self.durability.frozen = True
        self.messenger.closed = True
        if self.matrix is not None:
            self.matrix.closing()  # cut-short instructions resume; nobody is told "failed"
        self.hub.close()
        # Taken as journaling stops, so it holds what the journal holds; a restart then
        # replays no updates.
        await self.durability.snapshot_memory()
        await self.assistant.stop()

    # -- operations ----------------------------------------------------------------------
    async def submit(self, person: PersonId, text: str) -> InstructionRecord:
        """Admit an instruction of ``person`` (resolved from a name by the route): rate-check,
        journal it (one insert), queue it for the starter.

        The caller acknowledges once the insert is committed; starting it (the reasoner, the
        hooks, its first checkpoint) is the starter's job, so a submission never waits for
        anyone's step. A restart starts what was admitted and never started."""
        wait_s = self.rate.take(person)
        if wait_s is not None:
            name = self.office.person(person).name
            raise TooManyRequestsError(refusal_text(name, self.rate.per_minute, wait_s))
        instruction_id = new_instruction_id()
        with self.admission.arriving():  # no instruction starts meanwhile
            record = await self.journal.acreate_instruction(
                instruction_id, person, text, self.clock.now()
            )
        self.admission.admit(record)
        return record

    def _is_request(self, text: str, sender: str, *, strict: bool) -> bool:
        """Whether a direct message asks for something. The recognizer is made on the first
        message, not at start: its word forms (lemminflect's tables, about a third of a
        CPU-second) would delay every start for a message that may not come soon."""
        if self._request_check is None:
            from assistantx.agents.symbolic.requests import RequestRecognizer

            self._request_check = RequestRecognizer(self.office)
        return self._request_check(text, sender, strict=strict)

    async def _over_the_rate(self, message: InboundMessage) -> bool:
        """A direct message that would start one instruction too many is answered in words
        (once per window) instead; True: handled, nothing starts."""
        if not self._is_request(message.text, message.sender, strict=False):
            return False  # not a request: the assistant answers it as usual
        wait_s = self.rate.take(message.sender)
        if wait_s is None:
            return False
        logger.info("rate limit: a request from %s not started", message.sender)
        if self.rate.first_refusal(message.sender):
            name = self.office.person(message.sender).name
            await self.assistant.parts.messenger.send(
                OutboundMessage(
                    chat=ChatRef(kind="dm", id=message.sender),
                    text=refusal_text(name, self.rate.per_minute, wait_s),
                    idempotency_key=f"rate:{message.platform}:{message.event_id}",
                )
            )
        return True

    def instruction(self, instruction_id: str) -> InstructionRecord:
        return journaled_instruction(self.journal, instruction_id)

    unknown_instruction = staticmethod(unknown_instruction)

    async def cancel(self, instruction_id: str) -> bool:
        """Ask a running instruction to stop; False when it had already ended."""
        await self.journal.arequest_cancel(instruction_id)
        if await self.admission.withdraw(instruction_id):
            return True
        if instruction_id not in self.assistant.running:
            return False
        self.durability.cancelled.add(instruction_id)
        return self.assistant.cancel(instruction_id)


def lock_keys_for(settings: Settings, data_dir: Path) -> LockKeys:
    """The lock's keys by the rule of ``load_lock_keys``: key file, shared secret, else one
    generated once into the data dir.
    ``serve`` and ``lock-sim`` both call this, so on one data folder they agree by default."""
    secret = settings.lock_shared_key
    return load_lock_keys(
        key_file=settings.lock_key_file,
        secret=secret.get_secret_value() if secret is not None else None,
        fallback_file=data_dir / LOCK_KEYS_FILE,
    )
