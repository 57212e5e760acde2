"""Run one instruction in a fresh simulated office through the Assistant and the PPDR loop.

Shared by the dataset generator (to run the optimal policy) and the evaluator (every method).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from assistantx.agents.base import Reasoner
from assistantx.core.office import Office, PersonId
from assistantx.core.trace import Trace
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant, AssistantParts
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from assistantx.sim.requester import Wish

INSTRUCTION_ID = "ins-1"


@dataclass
class SimRun:
    trace: Trace
    sim: SimOffice


async def run_in_sim(
    office: Office,
    requester: PersonId,
    text: str,
    reasoner_factory: Callable[[], Reasoner],
    *,
    unavailable: Iterable[str] = (),
    limits: LoopLimits | None = None,
    reasoner_name: str = "reasoner",
    seed: int = 0,
    wish: Wish | None = None,
) -> SimRun:
    """``wish``: what the requester really wants (a task's goal), so they answer the
    assistant's questions as a person would; without it they answer generically."""
    sim = SimOffice(office, unavailable=tuple(unavailable), seed=seed)
    assistant = Assistant(
        AssistantParts(
            office=office,
            messenger=sim.messenger,
            robot=sim.robot,
            locker=sim.locker,
            clock=sim.clock,
            reasoner_factory=reasoner_factory,
            reasoner_name=reasoner_name,
            limits=limits or LoopLimits(),
        )
    )

    async def register(stm: ShortTermMemory) -> None:
        sim.register_instruction(stm.instruction_id, stm.requester, wish, text=stm.text)

    assistant.on_instruction_start(register)

    async def forget(stm: ShortTermMemory) -> None:  # nothing people write about it arrives later
        sim.end_instruction(stm.instruction_id)

    assistant.on_instruction_end(forget)
    await sim.locker.start()
    await assistant.start()
    try:
        stm = await assistant.submit(requester, text, instruction_id=INSTRUCTION_ID)
        stm = await assistant.wait(stm.instruction_id)
    finally:
        await assistant.stop()
        await sim.locker.stop()
    return SimRun(trace=stm.trace, sim=sim)
