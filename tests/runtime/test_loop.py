"""The loop's mechanics with a scripted reasoner: grounding, repetition, limits, the lease."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.agents.base import AgentContext
from assistantx.core.actions import Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.errors import ReasonerError
from assistantx.core.office import Office, load_office
from assistantx.core.trace import Decision, Percept, Plan
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import AvailabilityUpdate
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _run(
    office: Office,
    steps: list[Step],
    *,
    unavailable: tuple[str, ...] = (),
    max_steps: int = 20,
    reasoner: ScriptedReasoner | None = None,
) -> tuple[ShortTermMemory, SimOffice, ScriptedReasoner]:
    sim = SimOffice(office, unavailable=unavailable)
    scripted = reasoner or ScriptedReasoner(steps)
    assistant = sim_assistant(
        sim,
        lambda: scripted,
        reasoner_name="scripted",
        limits=LoopLimits(max_steps=max_steps),
    )
    stm = await run_one(sim, assistant, "lee", "bring me Zhang's stapler")
    return stm, sim, scripted


L1_STAPLER: list[Step] = [
    [Inquire(contact="zhang", question="Could you lend me your stapler?"), Wait(timeout_s=60)],
    [
        Inform(contact="zhang", content="The robot is coming for your stapler."),
        Move(place="zhang"),
        SendQR(contact="zhang", item="stapler:zhang"),
    ],
    [WaitInPlace(person="zhang")],
    [Move(place="lee"), SendQR(contact="lee", item="stapler:zhang", purpose="collect")],
    [WaitInPlace(person="lee")],
    [Stop(outcome="done", summary="Zhang's stapler is in your hands.")],
]


async def test_scripted_l1_reaches_the_goal_and_tells_the_requester(office: Office) -> None:
    stm, sim, _ = await _run(office, list(L1_STAPLER))
    assert stm.trace.outcome == "done"
    assert all(r.ok for r in stm.trace.actions()), [r.observation for r in stm.trace.actions()]
    assert sim.world.check({"holds": ["lee", "stapler:zhang"]})
    last = sim.messenger.sent[-1]
    assert last.chat.id == "lee" and last.text.startswith("[done]")
    assert len(stm.trace.steps) == 6


async def test_unknown_person_is_refused_and_fed_back(office: Office) -> None:
    steps: list[Step] = [
        [Inquire(contact="Zhangg Wie Wu", question="stapler?")],
        [Stop(outcome="failed", summary="gave up")],
    ]
    stm, sim, scripted = await _run(office, steps)
    first = stm.trace.steps[0].results[0]
    assert first.refused and "Unknown contact" in first.observation
    assert any("Unknown contact" in f for f in scripted.seen_feedback[1])
    assert all(m.chat.id == "lee" for m in sim.messenger.sent)  # nothing reached anyone else


async def test_repeated_action_without_new_information_is_refused(office: Office) -> None:
    again = Inform(contact="zhang", content="hello")
    steps: list[Step] = [[again], [again], [Stop(outcome="failed", summary="x")]]
    stm, sim, scripted = await _run(office, steps)
    second = stm.trace.steps[1].results[0]
    assert second.refused and "no new information" in second.observation
    assert sum(1 for m in sim.messenger.sent if m.chat.id == "zhang") == 1
    assert any("repeats" in f for f in scripted.seen_feedback[2])


async def test_repeat_after_new_information_is_allowed(office: Office) -> None:
    ask = Inquire(contact="zhang", question="Are you at your desk?")
    steps: list[Step] = [[ask, Wait(timeout_s=60)], [ask], [Stop(outcome="done", summary="x")]]
    stm, _, _ = await _run(office, steps)
    assert not stm.trace.steps[1].results[0].refused


async def test_step_limit_ends_and_tells_the_requester(office: Office) -> None:
    steps: list[Step] = [[Wait(timeout_s=5)] for _ in range(10)]
    stm, sim, _ = await _run(office, steps, max_steps=3)
    assert stm.trace.outcome == "failed"
    assert "3 steps" in (stm.trace.summary or "")
    assert sim.messenger.sent[-1].chat.id == "lee"


async def test_reflection_updates_reach_memory_and_the_next_decision(office: Office) -> None:
    def mark(ctx: object, results: list[object]) -> list[AvailabilityUpdate]:
        return [AvailabilityUpdate(person="Dr. Zhang", available=False, evidence="no reply")]

    reasoner = ScriptedReasoner(
        [
            [Inquire(contact="zhang", question="Stapler?"), Wait(timeout_s=30)],
            [Stop(outcome="unachievable", summary="nobody")],
        ],
        updates=mark,
    )
    stm, _, _ = await _run(office, [], unavailable=("zhang",), reasoner=reasoner)
    applied = stm.trace.steps[0].applied
    assert applied[0].update.person == "zhang" and applied[0].changed
    assert reasoner.seen_reflections[1] is not None
    assert reasoner.seen_reflections[1].verdict == "N"


async def test_two_instructions_share_the_robot_without_interleaving(office: Office) -> None:
    sim = SimOffice(office)

    def script(person: str) -> ScriptedReasoner:
        return ScriptedReasoner(
            [
                [Inform(contact=person, content="robot coming"), Move(place=person)],
                [Move(place="printer")],
                [Stop(outcome="done", summary="ok")],
            ]
        )

    reasoners = iter([script("zhang"), script("wang")])
    assistant = sim_assistant(sim, lambda: next(reasoners))
    await assistant.start()
    try:
        a = await assistant.submit("lee", "one")
        b = await assistant.submit("chen", "two")
        await asyncio.gather(assistant.wait(a.instruction_id), assistant.wait(b.instruction_id))
    finally:
        await assistant.stop()
    arrivals = [e.detail["place"] for e in sim.world.log if e.kind == "robot_arrived"]
    assert arrivals == ["desk_04", "print_room", "desk_06", "print_room"]
    assert any(s.queue for s in b.trace.steps)  # the second one saw itself queued


async def test_cancel_tells_the_requester(office: Office) -> None:
    sim = SimOffice(office)
    gate = asyncio.Event()
    perceiving = asyncio.Event()

    class Slow(ScriptedReasoner):
        async def perceive(self, ctx):  # type: ignore[no-untyped-def]
            perceiving.set()
            await gate.wait()
            return await super().perceive(ctx)

    assistant = sim_assistant(sim, lambda: Slow([]))
    await assistant.start()
    try:
        stm = await assistant.submit("lee", "anything")
        await asyncio.wait_for(perceiving.wait(), 10)  # the instruction is under way
        assert assistant.cancel(stm.instruction_id)
        with pytest.raises(asyncio.CancelledError):
            await assistant.wait(stm.instruction_id)
    finally:
        await assistant.stop()
    assert stm.trace.outcome == "failed"
    assert "cancelled" in sim.messenger.sent[-1].text


async def test_a_broken_reasoner_is_reported_in_words_with_details_in_the_trace(
    office: Office,
) -> None:
    class Broken(ScriptedReasoner):
        async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
            raise ReasonerError(f"model at http://10.1.2.3:8000 failed on {ctx.stm.instruction_id}")

    stm, sim, _ = await _run(office, [], reasoner=Broken([]))
    told = sim.messenger.sent[-1].text
    assert told == (
        "[failed] I could not complete this: my reasoning model did not give a usable answer."
    )
    assert stm.trace.summary == told.removeprefix("[failed] ")
    assert "http://10.1.2.3:8000" in stm.trace.steps[-1].feedback[0]  # for the operator
