"""Memory updates are grounded by the resolver's one rule, whoever proposes them: the loop
(the symbolic reasoner's path) and the LLM agents send "The Locker " or a person's display
name in any case to the same node as the canonical id."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.base import AgentContext
from assistantx.agents.llm import build_factory
from assistantx.core.actions import Inform, Stop, Wait
from assistantx.core.office import Office, load_office
from assistantx.core.trace import (
    Decision,
    Observation,
    Percept,
    Plan,
    SubGoal,
    Trace,
    TraceStep,
)
from assistantx.memory.graph import LOCKER, LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import (
    AvailabilityUpdate,
    ItemLocationUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)
from assistantx.runtime.assistant import Assistant, AssistantParts
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import ScriptedLLM
from helpers.llm_office import llm_model, llm_settings
from helpers.scripted_reasoner import ScriptedReasoner

# (holder, person) as a model or a person might write them; each must mean (locker, zhang).
SPELLINGS = [
    ("locker", "zhang"),
    ("The Locker ", "Zhang Wei"),
    ("LOCKER", "ZHANG WEI"),
    ("the robot's locker", "  zhang wei "),
    ("Robot Locker", "Dr. Zhang"),
]


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def updates(holder: str, person: str) -> list[MemoryUpdate]:
    return [
        ItemLocationUpdate(item="stapler:zhang", holder=holder, evidence="deposited"),
        AvailabilityUpdate(person=person, available=False, evidence="no reply"),
        OwnershipUpdate(person=person, item_type="stapler", owns=True, evidence="said so"),
    ]


def facts(ltm: LongTermMemory) -> tuple[Any, ...]:
    return (ltm.item_holder("stapler:zhang"), ltm.availability("zhang"), ltm.owners("stapler"))


def expected(office: Office) -> tuple[Any, ...]:
    ltm = LongTermMemory(office)
    for update in updates(LOCKER, "zhang"):
        ltm.apply(update, 0.0, "canonical")
    return facts(ltm)


@pytest.mark.parametrize(("holder", "person"), SPELLINGS)
def test_the_resolver_grounds_every_name_of_an_update(
    holder: str, person: str, office: Office
) -> None:
    grounded = [Resolver(office).ground_update(u) for u in updates(holder, person)]
    assert grounded == updates(LOCKER, "zhang")


def test_a_place_and_a_person_still_hold_items(office: Office) -> None:
    resolver = Resolver(office)
    assert resolver.holder("Zhang Wei") == "zhang"
    assert resolver.holder("meeting room") == "meeting_room"


@pytest.mark.parametrize(("holder", "person"), SPELLINGS)
async def test_the_loop_applies_updates_to_the_canonical_nodes(
    holder: str, person: str, office: Office
) -> None:
    def reflect(ctx: object, results: object) -> list[MemoryUpdate]:
        return updates(holder, person)

    reasoner = ScriptedReasoner(
        [[Inform(contact="lee", content="On it.")], [Stop(outcome="done", summary="ok")]],
        updates=reflect,
    )
    sim = SimOffice(office)
    ltm = LongTermMemory(office)
    assistant = Assistant(
        AssistantParts(
            office=office,
            messenger=sim.messenger,
            robot=sim.robot,
            locker=sim.locker,
            clock=sim.clock,
            reasoner_factory=lambda: reasoner,
            reasoner_name="scripted",
            ltm=ltm,
            limits=LoopLimits(max_steps=5),
        )
    )
    await sim.locker.start()
    await assistant.start()
    try:
        stm = await assistant.submit("lee", "bring me Zhang's stapler")
        stm = await assistant.wait(stm.instruction_id)
    finally:
        await assistant.stop()
        await sim.locker.stop()

    first = stm.trace.steps[0]
    assert not [f for f in first.feedback if "rejected" in f]
    assert [a.update for a in first.applied] == updates(LOCKER, "zhang")
    assert facts(ltm) == expected(office)


def context(office: Office) -> AgentContext:
    trace = Trace(instruction_id="i-4", requester="lee", text="x", reasoner="llm", started_at=0)
    trace.steps.append(TraceStep(index=0, started_at=0.0))
    stm = ShortTermMemory(instruction_id="i-4", requester="lee", text="x", trace=trace)
    return AgentContext(
        ltm=LongTermMemory(office), stm=stm, resolver=Resolver(office), step=0, now=0.0
    )


@pytest.mark.parametrize(("holder", "person"), SPELLINGS)
async def test_the_llm_reflection_grounds_updates_the_same_way(
    holder: str,
    person: str,
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    said = [u.model_dump(mode="json") for u in updates(holder, person)]
    scripted_llm.script("reflection", {"verdict": "Y", "reason": "done", "updates": said})
    reasoner = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))()
    plan = Plan(goal="g", subgoals=[SubGoal(description="s")])
    decision = Decision(actions=[Wait(reason="reply")])
    ctx = context(office)
    reflection = await reasoner.reflect(ctx, Percept(), plan, decision, [], Observation())
    await reasoner.stop()

    assert len(scripted_llm.requests) == 1  # accepted at once, nothing fed back
    assert reflection.updates == updates(LOCKER, "zhang")
    for update in reflection.updates:
        ctx.ltm.apply(update, 0.0, "i-4")
    assert facts(ctx.ltm) == expected(office)
