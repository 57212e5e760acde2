"""The Assistant: runs instructions concurrently over one Memory Unit and one set of adapters.

Inbound messages from every messenger land on one queue; one consumer routes each to the
instruction and question that asked for it, or, for a direct message that answers nothing,
starts a new instruction for its author. Each instruction is a PPDR loop coroutine; the robot
and its locker are leased to one instruction at a time.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import logging
from collections import OrderedDict
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field

from assistantx.adapters.lock.base import Locker
from assistantx.adapters.messenger.base import InboundMessage, Messenger
from assistantx.adapters.robot.base import RobotBase
from assistantx.clock import Clock
from assistantx.errors import GroundingError
from assistantx.executors import ExecutionContext, Executor
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.office import Office
from assistantx.ppdr.agents import Reasoner
from assistantx.ppdr.events import EventSink, TraceEvent
from assistantx.ppdr.lease import BodyLease
from assistantx.ppdr.loop import InstructionRunner, LoopLimits
from assistantx.replies import ReplyBox
from assistantx.trace import Trace

logger = logging.getLogger(__name__)

FINISHED_KEPT = 256

ReasonerFactory = Callable[[], Reasoner]
InstructionHook = Callable[[ShortTermMemory], Awaitable[None]]
# Claims a direct message that answers no open question (True: handled, e.g. a survey reply)
# before it would start a new instruction.
DirectMessageHook = Callable[[InboundMessage], Awaitable[bool]]


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


class Assistant:
    def __init__(self, parts: AssistantParts) -> None:
        self.parts = parts
        self.office = parts.office
        self.clock = parts.clock
        self.ltm = parts.ltm or LongTermMemory(parts.office)
        self.resolver = Resolver(parts.office)
        self.replies = ReplyBox()
        self.lease = BodyLease()
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
            )
        )
        self.running: dict[str, Running] = {}
        # The latest FINISHED_KEPT ended instructions (older ones are in the journal, if any):
        # a service running for months must not keep every instruction it ever ran.
        self.finished: OrderedDict[str, ShortTermMemory] = OrderedDict()
        self._sinks: list[EventSink] = []
        self._on_start: list[InstructionHook] = []
        self._on_end: list[InstructionHook] = []
        self._dm_hooks: list[DirectMessageHook] = []
        self._ids = itertools.count(1)
        self._dispatcher: asyncio.Task[None] | None = None
        self.unmatched: list[InboundMessage] = []

    # -- lifecycle -----------------------------------------------------------------------
    async def start(self) -> None:
        if self._dispatcher is not None:
            return
        self.parts.messenger.connect_inbox(self.inbox)  # type: ignore[arg-type]
        self._dispatcher = asyncio.create_task(self._dispatch(), name="assistant-dispatch")

    async def stop(self) -> None:
        for running in list(self.running.values()):
            running.task.cancel()
        for running in list(self.running.values()):
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await running.task
        if self._dispatcher is not None:
            await self.inbox.put(None)  # sentinel
            with contextlib.suppress(asyncio.CancelledError):
                await self._dispatcher
            self._dispatcher = None

    def subscribe(self, sink: EventSink) -> None:
        self._sinks.append(sink)

    def on_instruction_start(self, hook: InstructionHook) -> None:
        self._on_start.append(hook)

    def on_instruction_end(self, hook: InstructionHook) -> None:
        self._on_end.append(hook)

    def intercept_direct_messages(self, hook: DirectMessageHook) -> None:
        self._dm_hooks.append(hook)

    async def _emit(self, event: TraceEvent) -> None:
        for sink in self._sinks:
            await sink(event)

    # -- instructions --------------------------------------------------------------------
    def new_id(self) -> str:
        return f"ins-{next(self._ids)}"

    async def submit(
        self,
        requester: str,
        text: str,
        *,
        instruction_id: str | None = None,
        resume: ShortTermMemory | None = None,
    ) -> ShortTermMemory:
        """Start an instruction (or resume one from its journaled memory); returns its memory."""
        if resume is not None:
            stm = resume
        else:
            requester = self.resolver.person(requester)  # GroundingError for unknown people
            instruction_id = instruction_id or self.new_id()
            if instruction_id in self.running or instruction_id in self.finished:
                raise ValueError(f"instruction {instruction_id} exists already")
            stm = ShortTermMemory(
                instruction_id=instruction_id,
                requester=requester,
                text=text,
                trace=Trace(
                    instruction_id=instruction_id,
                    requester=requester,
                    text=text,
                    reasoner=self.parts.reasoner_name,
                    started_at=self.clock.now(),
                ),
            )
            stm.embodied.robot_place = self.parts.robot.state().place
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
        self.running[stm.instruction_id] = Running(stm, task, reasoner)
        return stm

    async def _run(self, runner: InstructionRunner, stm: ShortTermMemory) -> ShortTermMemory:
        try:
            await runner.run(stm)
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
        for hook in self._on_end:
            try:
                await hook(stm)
            except Exception:
                logger.exception("instruction end hook failed")
        return stm

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
            except Exception:
                logger.exception("could not handle inbound message %s", message.event_id)
            try:
                # Also after a failure: a message that broke the handler would break it again.
                await self.parts.messenger.acknowledge(message)
            except Exception:
                logger.exception("could not acknowledge inbound message %s", message.event_id)

    async def handle_inbound(self, message: InboundMessage) -> str | None:
        """Route a reply to its instruction, or start an instruction from a direct message."""
        routed = self.replies.route(message)
        if routed is not None:
            return routed
        if message.chat.kind == "dm" and message.text.strip():
            try:
                self.resolver.person(message.sender)
            except GroundingError:
                logger.warning("message from unknown sender %s ignored", message.sender)
                return None
            for hook in self._dm_hooks:
                if await hook(message):
                    return None
            stm = await self.submit(message.sender, message.text)
            return stm.instruction_id
        self.unmatched.append(message)
        return None
