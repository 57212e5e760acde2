"""An office to run scripted instructions in (the scripted reasoner is the fake for the LLM),
with a Surveyor attached."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from dataclasses import dataclass
from pathlib import Path

from assistantx.core.actions import Action
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.survey import SurveyPolicy
from assistantx.feedback.surveyor import Surveyor
from assistantx.feedback.walking import DistanceFn
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner


@dataclass
class Harness:
    sim: SimOffice
    assistant: Assistant
    surveyor: Surveyor
    store: FeedbackStore
    scripts: list[list[list[Action]]]
    handled: dict[str, asyncio.Event]

    async def run(self, requester: str, text: str, steps: list[list[Action]]) -> ShortTermMemory:
        """Run one instruction to its end (the survey is sent by the end hook)."""
        self.scripts.append(steps)
        stm = await self.assistant.submit(requester, text)
        return await self.assistant.wait(stm.instruction_id)

    async def say(self, person: str, text: str) -> None:
        """``person`` writes to the assistant in their direct chat; wait until it is handled."""
        message = self.sim.messenger.post(person, ChatRef(kind="dm", id=person), text)
        handled = self.handled.setdefault(message.event_id, asyncio.Event())
        try:
            await asyncio.wait_for(handled.wait(), 10)
        except TimeoutError:
            raise AssertionError(f"the assistant did not handle {text!r} from {person}") from None

    def texts_to(self, person: str) -> list[str]:
        return [m.text for m in self.sim.messenger.sent if m.chat == ChatRef(kind="dm", id=person)]


@asynccontextmanager
async def harness(
    office: Office,
    db: Path,
    *,
    distance: DistanceFn | None = None,
    policy: SurveyPolicy | None = None,
) -> AsyncIterator[Harness]:
    sim = SimOffice(office, distance=distance)
    scripts: list[list[list[Action]]] = []
    assistant = sim_assistant(
        sim,
        lambda: ScriptedReasoner(scripts.pop(0)),
        reasoner_name="played",
        limits=LoopLimits(max_steps=10),
    )
    # The assistant acknowledges each inbound message once it has handled it.
    handled: dict[str, asyncio.Event] = {}
    acknowledge = sim.messenger.acknowledge

    async def note_handled(message: InboundMessage) -> None:
        await acknowledge(message)
        handled.setdefault(message.event_id, asyncio.Event()).set()

    sim.messenger.acknowledge = note_handled  # type: ignore[method-assign]
    store = FeedbackStore.open(db)
    surveyor = Surveyor(office, store, sim.messenger, sim.clock, distance=distance, policy=policy)
    surveyor.attach(assistant)
    await assistant.start()
    try:
        yield Harness(sim, assistant, surveyor, store, scripts, handled)
    finally:
        await assistant.stop()
        store.close()
