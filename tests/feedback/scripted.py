"""A reasoner that plays a fixed list of decisions (the fake for the LLM), and an office to
run instructions in with a Surveyor attached."""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from dataclasses import dataclass
from pathlib import Path

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.actions import Action, Wait
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.core.trace import (
    ActionResult,
    Decision,
    Observation,
    Percept,
    Plan,
    Reflection,
    SubGoal,
)
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.survey import SurveyPolicy
from assistantx.feedback.surveyor import Surveyor
from assistantx.feedback.walking import DistanceFn
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant, AssistantParts
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice


class PlayedReasoner(Reasoner):
    name = "played"

    def __init__(self, steps: list[list[Action]]) -> None:
        self.steps = list(steps)

    async def perceive(self, ctx: AgentContext) -> Percept:
        return Percept(summary="played")

    async def plan(self, ctx: AgentContext, percept: Percept) -> Plan:
        return Plan(goal="played", subgoals=[SubGoal(description="play the steps")])

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        actions = self.steps.pop(0) if self.steps else [Wait(timeout_s=10)]
        return Decision(actions=actions)

    async def reflect(
        self,
        ctx: AgentContext,
        percept: Percept,
        plan: Plan,
        decision: Decision,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        return Reflection(verdict="Y" if all(r.ok for r in results) else "N", reason="played")


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
    assistant = Assistant(
        AssistantParts(
            office=office,
            messenger=sim.messenger,
            robot=sim.robot,
            locker=sim.locker,
            clock=sim.clock,
            reasoner_factory=lambda: PlayedReasoner(scripts.pop(0)),
            reasoner_name="played",
            limits=LoopLimits(max_steps=10),
        )
    )

    async def register(stm: ShortTermMemory) -> None:
        sim.register_instruction(stm.instruction_id, stm.requester)

    assistant.on_instruction_start(register)
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
