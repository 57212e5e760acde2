"""The simulated office wired to an Assistant, as the tests build it.

The simulator plays the physical world and the people; the Assistant runs the real loop,
executors and memory on the simulator's messenger, robot, locker and clock. Each instruction
is registered with the simulation as it starts (its requester knows what the robot comes for).
A test that needs another robot or messenger sets it on the ``SimOffice`` before wiring.
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Any

from assistantx.core.ports.messenger import Messenger
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant, AssistantParts, ReasonerFactory
from assistantx.runtime.executors import ExecutionContext, Executor
from assistantx.runtime.replies import ReplyBox
from assistantx.sim.office import SimOffice


def sim_assistant(
    sim: SimOffice,
    reasoner_factory: ReasonerFactory,
    *,
    messenger: Messenger | None = None,
    **parts: Any,
) -> Assistant:
    """An Assistant on ``sim``; ``messenger``: a real one instead of the simulated people's;
    ``parts``: further ``AssistantParts`` fields (reasoner_name, limits, ltm...)."""
    assistant = Assistant(
        AssistantParts(
            office=sim.office,
            messenger=messenger or sim.messenger,
            robot=sim.robot,
            locker=sim.locker,
            clock=sim.clock,
            reasoner_factory=reasoner_factory,
            **parts,
        )
    )

    async def register(stm: ShortTermMemory) -> None:
        sim.register_instruction(stm.instruction_id, stm.requester, text=stm.text)

    assistant.on_instruction_start(register)
    return assistant


@asynccontextmanager
async def started(sim: SimOffice, assistant: Assistant) -> AsyncIterator[Assistant]:
    """The simulated locker and the assistant, started; both stopped on exit."""
    await sim.locker.start()
    await assistant.start()
    try:
        yield assistant
    finally:
        await assistant.stop()
        await sim.locker.stop()


@asynccontextmanager
async def sim_executor(sim: SimOffice, **context: Any) -> AsyncIterator[Executor]:
    """An Executor on ``sim``'s messenger, robot, locker and clock, with fresh memory and no
    replies yet; the simulated locker started, and stopped on exit. ``context``: further
    ``ExecutionContext`` fields (retire_codes...)."""
    ctx = ExecutionContext(
        office=sim.office,
        ltm=LongTermMemory(sim.office),
        messenger=sim.messenger,
        robot=sim.robot,
        locker=sim.locker,
        clock=sim.clock,
        replies=ReplyBox(),
        **context,
    )
    await sim.locker.start()
    try:
        yield Executor(ctx)
    finally:
        await sim.locker.stop()


async def run_one(
    sim: SimOffice, assistant: Assistant, requester: str, text: str
) -> ShortTermMemory:
    """One instruction from start to end on a started-and-stopped assistant."""
    async with started(sim, assistant):
        stm = await assistant.submit(requester, text)
        return await assistant.wait(stm.instruction_id)
