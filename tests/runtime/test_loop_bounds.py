"""The loop's bounds and accounting: waits with nothing new, calls of a failing agent, the
wall clock, and QR codes only for people who agreed to the hand-over."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.agents.base import AgentContext
from assistantx.core.actions import Inquire, Move, SendQR, Stop, Wait
from assistantx.core.errors import ModelBehaviorError
from assistantx.core.office import Office, load_office
from assistantx.core.trace import AgentCall, Decision, Percept, Plan
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _run(
    office: Office,
    reasoner: ScriptedReasoner,
    *,
    unavailable: tuple[str, ...] = (),
    limits: LoopLimits | None = None,
) -> tuple[ShortTermMemory, SimOffice]:
    sim = SimOffice(office, unavailable=unavailable)
    assistant = sim_assistant(
        sim,
        lambda: reasoner,
        reasoner_name="scripted",
        limits=limits or LoopLimits(max_steps=8),
    )
    stm = await run_one(sim, assistant, "lee", "bring me Zhang's stapler")
    return stm, sim


async def test_a_wait_with_nothing_new_is_refused_whatever_its_wording(office: Office) -> None:
    steps: list[Step] = [
        [Wait(reason="a reply", timeout_s=60)],
        [Wait(reason="a reply, again", timeout_s=30)],
        [Stop(outcome="failed", summary="Nobody answered.")],
    ]
    stm, _ = await _run(office, ScriptedReasoner(steps))
    first, second = stm.trace.steps[0].results[0], stm.trace.steps[1].results[0]
    assert not first.refused  # it ran (and timed out)
    assert second.refused
    assert "no new information" in second.observation


async def test_a_wait_after_a_new_question_is_allowed(office: Office) -> None:
    steps: list[Step] = [
        [Wait(reason="a reply", timeout_s=60)],
        [Inquire(contact="zhang", question="Could you lend Lee your stapler?"), Wait()],
        [Stop(outcome="done", summary="Asked.")],
    ]
    stm, _ = await _run(office, ScriptedReasoner(steps))
    assert [r.refused for r in stm.trace.steps[1].results] == [False, False]


class _FailingDecision(ScriptedReasoner):
    """Perception costs a call; Decision costs three attempts and then gives up."""

    async def decide(self, ctx: AgentContext, percept: Percept, plan: Plan) -> Decision:
        ctx.record(AgentCall(agent="decision", prompt_tokens=900, completion_tokens=40, attempts=3))
        raise ModelBehaviorError("decision: no valid Decision after 3 attempt(s); last error: x")


async def test_calls_of_an_agent_that_raised_are_counted(office: Office) -> None:
    stm, sim = await _run(office, _FailingDecision([]))
    usage = stm.trace.usage
    assert stm.trace.outcome == "failed"
    assert usage.llm_calls == 1 + 3  # perception's call and every decision attempt
    assert usage.prompt_tokens == 900
    assert [c.agent for c in stm.trace.steps[0].calls] == ["perception", "decision"]
    told = sim.messenger.sent[-1]
    assert told.chat.id == "lee"
    assert "language model kept giving answers" in told.text
    assert "attempt" not in told.text


class _SlowPerception(ScriptedReasoner):
    async def perceive(self, ctx: AgentContext) -> Percept:
        await asyncio.sleep(30)
        return Percept()


async def test_the_wall_clock_bounds_an_instruction(office: Office) -> None:
    stm, sim = await _run(office, _SlowPerception([]), limits=LoopLimits(wall_s=0.3))
    assert stm.trace.outcome == "failed"
    assert stm.trace.summary == "I ran out of time for this task."
    assert sim.messenger.sent[-1].chat.id == "lee"


async def test_a_qr_code_to_someone_who_never_answered_is_refused(office: Office) -> None:
    # zhang is away: a reasoner that skips the question must not hand him a deposit code
    steps: list[Step] = [
        [Move(place="zhang"), SendQR(contact="zhang", item="stapler:zhang", purpose="deposit")],
        [Stop(outcome="failed", summary="Zhang did not answer.")],
    ]
    stm, sim = await _run(office, ScriptedReasoner(steps), unavailable=("zhang",))
    move, qr = stm.trace.steps[0].results
    assert move.ok
    assert qr.refused
    assert "not agreed to this hand-over" in qr.observation
    assert not any(m.chat.id == "zhang" for m in sim.messenger.sent)


async def test_a_qr_code_after_the_person_answered_goes_out(office: Office) -> None:
    steps: list[Step] = [
        [Inquire(contact="zhang", question="Could you lend Lee your stapler?"), Wait()],
        [Move(place="zhang"), SendQR(contact="zhang", item="stapler:zhang", purpose="deposit")],
        [Stop(outcome="failed", summary="Stopping here.")],
    ]
    stm, _ = await _run(office, ScriptedReasoner(steps))
    assert [r.ok for r in stm.trace.steps[1].results] == [True, True]
