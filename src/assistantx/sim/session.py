"""A hand-driven session in the simulated office: ground and execute actions one by one.

This is what ``assistantx sim`` and the foundation tests use to drive the simulator as a
person would, with the same grounding and executors the PPDR loop uses.
"""

from __future__ import annotations

import asyncio
from types import TracebackType
from typing import Self

from assistantx.core.actions import Action
from assistantx.core.clock import Clock
from assistantx.core.errors import GroundingError
from assistantx.core.lifecycle import cancel_and_wait
from assistantx.core.office import Office
from assistantx.core.ports.lock import Locker
from assistantx.core.ports.messenger import InboundMessage
from assistantx.core.ports.robot import RobotBase
from assistantx.core.trace import ActionResult
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.executors import ExecutionContext, Executor
from assistantx.runtime.replies import ReplyBox
from assistantx.sim.office import SimOffice


class SimSession:
    def __init__(
        self,
        office: Office,
        *,
        requester: str,
        text: str = "(driven by hand)",
        unavailable: tuple[str, ...] = (),
        instruction_id: str = "sim-1",
        robot: RobotBase | None = None,
        locker: Locker | None = None,
        clock: Clock | None = None,
    ) -> None:
        """``robot``, ``locker``, ``clock``: as for ``SimOffice`` (default: all simulated)."""
        self.office = office
        self.sim = SimOffice(
            office, unavailable=unavailable, robot=robot, locker=locker, clock=clock
        )
        self.ltm = LongTermMemory(office)
        self.resolver = Resolver(office)
        self.replies = ReplyBox()
        self.inbox: asyncio.Queue[InboundMessage] = asyncio.Queue()
        self.sim.messenger.connect_inbox(self.inbox)
        self.executor = Executor(
            ExecutionContext(
                office=office,
                ltm=self.ltm,
                messenger=self.sim.messenger,
                robot=self.sim.robot,
                locker=self.sim.locker,
                clock=self.sim.clock,
                replies=self.replies,
            )
        )
        requester = self.resolver.person(requester)
        self.stm = ShortTermMemory.begin(
            instruction_id, requester, text, reasoner="hand", started_at=self.sim.clock.now()
        )
        self.stm.embodied.robot_place = office.robot.home
        self.sim.register_instruction(instruction_id, requester)
        self.unmatched: list[InboundMessage] = []
        self._pump: asyncio.Task[None] | None = None
        self._count = 0

    async def __aenter__(self) -> Self:
        await self.sim.locker.start()
        self._pump = asyncio.create_task(self._route())
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        await cancel_and_wait(self._pump)
        await self.sim.aclose()
        await self.sim.locker.stop()

    async def _route(self) -> None:
        while True:
            message = await self.inbox.get()
            if self.replies.route(message) is None:
                self.unmatched.append(message)

    async def do(self, action: Action) -> ActionResult:
        """Ground ``action`` (raises GroundingError) and execute it."""
        grounded = self.resolver.ground(action)
        self._count += 1
        return await self.executor.execute(self.stm, grounded, f"hand:{self._count}")

    async def try_do(self, action: Action) -> ActionResult | GroundingError:
        try:
            return await self.do(action)
        except GroundingError as exc:
            return exc
