"""The Assistant: runs instructions concurrently over one Memory Unit and one set of adapters.

Inbound messages from every messenger land on one queue; one consumer routes each to the
instruction and question that asked for it, or, for a direct message that answers nothing,
starts a new instruction for its author. Each instruction is a PPDR loop coroutine; the robot
and its locker are leased to one instruction at a time.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import secrets
from collections import OrderedDict
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from typing import Protocol

from assistantx.agents.base import Reasoner, ReasonerFactory
from assistantx.core.clock import Clock
from assistantx.core.errors import GroundingError
from assistantx.core.events import EventSink, TraceEvent
from assistantx.core.isolation import SkippedEvents
from assistantx.core.office import Office, PersonId
from assistantx.core.ports.lock import Locker
from assistantx.core.ports.messenger import (
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
)
from assistantx.core.ports.robot import RobotBase
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.executors import CodeRecords, ExecutionContext, Executor
from assistantx.runtime.fleet import FleetLease
from assistantx.runtime.lease import BodyLease
from assistantx.runtime.loop import InstructionRunner, LoopLimits
from assistantx.runtime.replies import ReplyBox
from assistantx.runtime.returns import items_to_return, return_items

logger = logging.getLogger(__name__)

FINISHED_KEPT = 256
# Unmatched messages kept for a look (tests, debugging), the latest; between UNMATCHED_KEPT and
# twice as many. Every message is journaled by its messenger; a group the assistant sits in
# (Matrix) talks among itself all day, and each word nobody asked for was kept for good.
UNMATCHED_KEPT = 256

InstructionHook = Callable[[ShortTermMemory], Awaitable[None]]
# Called with the ended instruction's id when its give-back errand is over (not when a
# shutdown cut it short: it starts again on the next start).
GiveBackHook = Callable[[str], Awaitable[None]]
# Claims a direct message that answers no open question (True: handled, e.g. a survey reply)
# before it would start a new instruction.
DirectMessageHook = Callable[[InboundMessage], Awaitable[bool]]


class RequestCheck(Protocol):
    """Whether a direct message is a request; ``strict``: only explicit wording counts (the
    sender was just contacted by an instruction that has ended)."""

    def __call__(self, text: str, sender: str, *, strict: bool) -> bool: ...


def new_instruction_id() -> str:
    """A fresh instruction id, unique for ever: random, not a counter that restarts with the
    process (a restarted service must not hand out an id its journal holds already)."""
    return f"ins-{secrets.token_hex(6)}"


@dataclass
class Running:
    stm: ShortTermMemory
    task: asyncio.Task[ShortTermMemory]
    reasoner: Reasoner


@dataclass
class AssistantParts:
    office: Office
    messenger: Messenger
    robot: RobotBase
    locker: Locker
    clock: Clock
    reasoner_factory: ReasonerFactory
    reasoner_name: str = "symbolic"
    ltm: LongTermMemory | None = None
    limits: LoopLimits = field(default_factory=LoopLimits)
    # None: every direct message that answers nothing starts an instruction.
    is_request: RequestCheck | None = None
    # Journals codes as revoked before the lock withdraws them (``ExecutionContext``).
    retire_codes: Callable[[list[str]], Awaitable[None]] | None = None
    # Journals the code each send minted, by its key (``ExecutionContext.code_records``).
    code_records: CodeRecords | None = None
    # Several robots (runtime.fleet): their lease; ``robot`` and ``locker`` are then the
    # fleet's FleetRobot and FleetLocker. None: the one robot's BodyLease.
    fleet: FleetLease | None = None


class Assistant:
    def __init__(self, parts: AssistantParts) -> None:
        self.parts = parts
        self.office = parts.office
        self.clock = parts.clock
        self.ltm = parts.ltm or LongTermMemory(parts.office)
        self.resolver = Resolver(parts.office)
        # A late reply is looked up in ``finished``: the box remembers as many ended ones.
        self.replies = ReplyBox(is_member=self._is_member, ended_kept=FINISHED_KEPT)
        self.lease: BodyLease | FleetLease = parts.fleet or BodyLease()
        self.inbox: asyncio.Queue[InboundMessage | None] = asyncio.Queue()
        self.executor = Executor(
            ExecutionContext(
                office=parts.office,
                ltm=self.ltm,
                messenger=parts.messenger,
                robot=parts.robot,
                locker=parts.locker,
                clock=parts.clock,
                replies=self.replies,
                retire_codes=parts.retire_codes,
                code_records=parts.code_records,
            )
        )
        self.running: dict[str, Running] = {}
        # Awaited before the reasoner factory is called: a factory still being built (the
        # service's warm-up thread after ready) is waited for off the loop, whoever starts the
        # instruction (an admitted POST, a direct message, a resumed one).
        self.reasoner_ready: Callable[[], Awaitable[None]] | None = None
        # The latest FINISHED_KEPT ended instructions (older ones are in the journal, if any):
        # a service running for months must not keep every instruction it ever ran.
        self.finished: OrderedDict[str, ShortTermMemory] = OrderedDict()
        self._sinks: list[EventSink] = []
        self._on_start: list[InstructionHook] = []
        self._on_end: list[InstructionHook] = []
        self._dm_hooks: list[DirectMessageHook] = []
        self._on_given_back: list[GiveBackHook] = []
        self._dispatcher: asyncio.Task[None] | None = None
        self._errands: set[asyncio.Task[None]] = set()  # items going back to their owners
        # Every instruction's task until it is done: one that has left ``running`` may still
        # be in its end hooks (they write to the journal), which a stop must wait for.
        self._instruction_tasks: set[asyncio.Task[ShortTermMemory]] = set()
        self._stopping = False
        self.unmatched: list[InboundMessage] = []
        self.skipped = SkippedEvents("dispatch")  # inbound messages whose handling raised

    # -- lifecycle -----------------------------------------------------------------------
    async def start(self) -> None:
        if self._dispatcher is not None:
            return
        self.parts.messenger.connect_inbox(self.inbox)  # type: ignore[arg-type]
        self._dispatcher = asyncio.create_task(self._dispatch(), name="assistant-dispatch")

    async def stop(self) -> None:
        # Instructions cut short by a shutdown resume on the next start: keep their codes.
        self._stopping = True
        for running in list(self.running.values()):
            running.task.cancel()
        for running in list(self.running.values()):
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await running.task
        if self._instruction_tasks:  # ended just before the stop: their end hooks finish
            await asyncio.gather(*self._instruction_tasks, return_exceptions=True)
        for errand in list(self._errands):
            errand.cancel()
        if self._errands:
            await asyncio.gather(*self._errands, return_exceptions=True)
        if self._dispatcher is not None:
            await self.inbox.put(None)  # sentinel
            with contextlib.suppress(asyncio.CancelledError):
                await self._dispatcher
            self._dispatcher = None

    def _is_member(self, person: str, group: str) -> bool:
        return any(g.id == group and person in g.members for g in self.office.groups)

    def subscribe(self, sink: EventSink) -> None:
        self._sinks.append(sink)

    def on_instruction_start(self, hook: InstructionHook) -> None:
        self._on_start.append(hook)

    def on_instruction_end(self, hook: InstructionHook) -> None:
        self._on_end.append(hook)

    def on_give_back_end(self, hook: GiveBackHook) -> None:
        self._on_given_back.append(hook)

    def intercept_direct_messages(self, hook: DirectMessageHook) -> None:
        self._dm_hooks.append(hook)

    async def _emit(self, event: TraceEvent) -> None:
        for sink in self._sinks:
            await sink(event)

    # -- instructions --------------------------------------------------------------------
    def new_id(self) -> str:
        return new_instruction_id()

    async def submit(
        self,
        requester: PersonId,
        text: str,
        *,
        instruction_id: str | None = None,
        resume: ShortTermMemory | None = None,
    ) -> ShortTermMemory:
        """Start an instruction (or resume one from its journaled memory); returns its memory.

        ``requester`` was resolved from a name at the edge (the API, the command line, the
        inbound message in ``handle_inbound``, the dataset): it is not resolved again here."""
        if resume is not None:
            stm = resume
        else:
            instruction_id = instruction_id or self.new_id()
            if instruction_id in self.running or instruction_id in self.finished:
                raise ValueError(f"instruction {instruction_id} exists already")
            stm = ShortTermMemory.begin(
                instruction_id,
                requester,
                text,
                reasoner=self.parts.reasoner_name,
                started_at=self.clock.now(),
            )
            stm.embodied.robot_place = self.parts.robot.state().place
        if self.reasoner_ready is not None:
            await self.reasoner_ready()
        reasoner = self.parts.reasoner_factory()
        await reasoner.start()  # its stop() runs when the instruction ends, in _run
        runner = InstructionRunner(
            ltm=self.ltm,
            resolver=self.resolver,
            executor=self.executor,
            reasoner=reasoner,
            lease=self.lease,
            limits=self.parts.limits,
            emit=self._emit,
        )
        for hook in self._on_start:
            await hook(stm)
        task = asyncio.create_task(self._run(runner, stm), name=stm.instruction_id)
        self._instruction_tasks.add(task)
        task.add_done_callback(self._instruction_tasks.discard)
        self.running[stm.instruction_id] = Running(stm, task, reasoner)
        return stm

    async def _run(self, runner: InstructionRunner, stm: ShortTermMemory) -> ShortTermMemory:
        ended = False
        try:
            await runner.run(stm)
            ended = True
        finally:
            self.running.pop(stm.instruction_id, None)
            self.executor.forget(stm.instruction_id)
            self.finished[stm.instruction_id] = stm
            while len(self.finished) > FINISHED_KEPT:
                self.finished.popitem(last=False)
            try:
                await runner.reasoner.stop()
            except Exception:
                logger.exception("could not stop the reasoner of %s", stm.instruction_id)
            # Ended, or cancelled by a person (not cut short by a shutdown: that resumes).
            if ended or not self._stopping:
                await self._revoke_codes(stm)
                await self._end_hooks(stm)
                self._give_back(stm)
        return stm

    def _give_back(self, stm: ShortTermMemory) -> None:
        """Someone's item is still in the locker: take it back to them (``returns``)."""
        self.give_back(stm)

    def give_back(self, ended: ShortTermMemory, *, attempt: int = 0) -> bool:
        """Start the errand that returns what ``ended`` left in the locker (also one cut short
        by a restart: ``attempt`` > 0); False when there is nothing to return."""
        if self._stopping or not items_to_return(self.office, ended):
            return False
        errand = asyncio.create_task(
            self._errand(ended, attempt), name=f"{ended.instruction_id}.return"
        )
        self._errands.add(errand)
        errand.add_done_callback(self._errands.discard)
        return True

    async def _errand(self, stm: ShortTermMemory, attempt: int) -> None:
        try:
            await return_items(
                self.office, self.resolver, self.executor, self.lease, stm, attempt=attempt
            )
        except asyncio.CancelledError:
            raise  # a shutdown: the errand is not over, it starts again on the next start
        except Exception:
            logger.exception("could not give back what %s left in the locker", stm.instruction_id)
        for hook in self._on_given_back:
            try:
                await hook(stm.instruction_id)
            except Exception:
                logger.exception("give-back end hook failed")

    async def _end_hooks(self, stm: ShortTermMemory) -> None:
        for hook in self._on_end:
            try:
                await hook(stm)
            except Exception:
                logger.exception("instruction end hook failed")

    async def _revoke_codes(self, stm: ShortTermMemory) -> None:
        """The instruction ended (done, failed, cancelled): none of its codes may open the
        locker any more."""
        try:
            revoked = await self.executor.revoke_codes(stm)
        except Exception:
            logger.exception("could not revoke the codes of %s", stm.instruction_id)
            return
        if revoked:
            logger.info("revoked %d unused code(s) of %s", revoked, stm.instruction_id)

    async def wait(self, instruction_id: str) -> ShortTermMemory:
        if instruction_id in self.running:
            return await self.running[instruction_id].task
        return self.finished[instruction_id]

    def cancel(self, instruction_id: str) -> bool:
        running = self.running.get(instruction_id)
        if running is None:
            return False
        running.task.cancel()
        return True

    def get(self, instruction_id: str) -> ShortTermMemory | None:
        running = self.running.get(instruction_id)
        return running.stm if running else self.finished.get(instruction_id)

    # -- inbound -------------------------------------------------------------------------
    async def _dispatch(self) -> None:
        while True:
            message = await self.inbox.get()
            if message is None:
                return
            try:
                await self.handle_inbound(message)
            except Exception as exc:
                self.skipped.skip("dispatch", message.event_id, "handling", exc)
            try:
                # Also after a failure: a message that broke the handler would break it again.
                await self.parts.messenger.acknowledge(message)
            except Exception:
                logger.exception("could not acknowledge inbound message %s", message.event_id)

    async def handle_inbound(self, message: InboundMessage) -> str | None:
        """Route a reply to its instruction, or start an instruction from a direct message
        that is a request; a late reply to an ended instruction or a message that asks for
        nothing is acknowledged in words instead."""
        routed = self.replies.route(message)
        if routed is not None:
            return routed
        if message.chat.kind == "dm" and message.text.strip():
            try:
                sender = self.resolver.person(message.sender)  # the messenger's edge
            except GroundingError:
                logger.warning("message from unknown sender %s ignored", message.sender)
                return None
            for hook in self._dm_hooks:
                if await hook(message):
                    return None
            refusal = self._not_a_new_request(message)
            if refusal is not None:
                await self._acknowledge(message, refusal)
                return None
            stm = await self.submit(sender, message.text)
            return stm.instruction_id
        self.unmatched.append(message)
        if len(self.unmatched) > 2 * UNMATCHED_KEPT:  # trimmed in bulk, not at every message
            del self.unmatched[:-UNMATCHED_KEPT]
        return None

    def _not_a_new_request(self, message: InboundMessage) -> str | None:
        """Why ``message`` starts no instruction, in words for its author; None: it does."""
        # A reply to one of our questions that no open question took: its instruction ended.
        if message.in_reply_to is not None and _names_a_question(message.in_reply_to):
            return (
                "Thanks. The request I asked you about has already ended, so I did not act "
                "on your reply."
            )
        check = self.parts.is_request
        if check is None:
            return None
        ended = self.replies.ended_instruction(message)
        ended_stm = self.finished.get(ended) if ended is not None else None
        contacted = ended_stm is not None and ended_stm.requester != message.sender
        if check(message.text, message.sender, strict=contacted):
            return None
        if contacted:
            return (
                "Thanks. The request I contacted you about has already ended, so I did not "
                "act on this message. If you need something yourself, please tell me what, "
                "and for whom."
            )
        return (
            "I did not find a request in your message, so I did nothing. Please tell me "
            "what you need, and for whom."
        )

    async def _acknowledge(self, message: InboundMessage, text: str) -> None:
        logger.info("message %s acknowledged, not executed", message.event_id)
        reply = OutboundMessage(
            chat=ChatRef(kind="dm", id=message.sender),
            text=text,
            idempotency_key=f"ack:{message.platform}:{message.event_id}",
        )
        try:
            await self.parts.messenger.send(reply)
        except Exception:
            logger.exception("could not acknowledge message %s in words", message.event_id)


def _names_a_question(reference: str) -> bool:
    """Whether a reply reference is one of our question ids (``<instruction id>:<key>``)."""
    instruction_id, sep, key = reference.partition(":")
    return bool(sep and key) and instruction_id.startswith("ins-")
