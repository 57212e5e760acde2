"""Running one instruction through the Assistant in the simulated office (a test helper)."""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from dataclasses import dataclass

from assistantx.agents.symbolic import build_factory
from assistantx.core.events import TraceEvent
from assistantx.core.office import Office
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant

EventHook = Callable[[TraceEvent, SimOffice], Awaitable[None]]


@dataclass
class Run:
    stm: ShortTermMemory
    sim: SimOffice
    assistant: Assistant

    @property
    def actions(self) -> list[str]:
        return [r.action.type for r in self.stm.trace.actions() if not r.refused]


async def run_instruction(
    office: Office,
    requester: str,
    text: str,
    *,
    unavailable: tuple[str, ...] = (),
    on_event: EventHook | None = None,
) -> Run:
    sim = SimOffice(office, unavailable=unavailable)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    if on_event is not None:
        hook = on_event

        async def sink(event: TraceEvent) -> None:
            await hook(event, sim)

        assistant.subscribe(sink)
    stm = await run_one(sim, assistant, requester, text)
    return Run(stm, sim, assistant)
