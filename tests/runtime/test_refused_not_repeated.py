"""A hand-over the consent guard refused is never sent again unchanged: whichever reasoner
chose it (the loop enforces this, so the symbolic, LLM and baseline reasoners alike), a second
identical try with nothing new in between is not sent, and the requester reads, in words,
what could not be done and why, instead of the instruction running to the step limit."""

from __future__ import annotations

import pytest

from assistantx.core.actions import Action, Inquire, SendQR, Stop, Wait
from assistantx.core.office import Office, load_office
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _scripted(office: Office, steps: list[Step], text: str) -> tuple[object, SimOffice]:
    sim = SimOffice(office)
    assistant = sim_assistant(
        sim,
        lambda: ScriptedReasoner(steps),
        reasoner_name="scripted",
        limits=LoopLimits(max_steps=30),
    )
    return await run_one(sim, assistant, "lee", text), sim


def _guard_refusals(stm: object, action: Action) -> int:
    return sum(
        1
        for r in stm.trace.actions()  # type: ignore[attr-defined]
        if r.action.signature() == action.signature() and r.error == "not_a_party"
    )


async def test_a_code_to_someone_never_named_is_tried_once_then_the_requester_is_told(
    office: Office,
) -> None:
    # Wang answered, but nobody named Wang as the one to get Zhang's stapler
    to_wang = SendQR(contact="wang", item="stapler:zhang", purpose="collect")
    asked: Step = [Inquire(contact="wang", question="Could you take a stapler?"), Wait()]
    stm, sim = await _scripted(office, [asked, *([[to_wang]] * 20)], "bring me Zhang's stapler")
    assert _guard_refusals(stm, to_wang) == 1
    assert stm.trace.outcome == "failed"  # type: ignore[attr-defined]
    assert len(stm.trace.steps) <= 4  # type: ignore[attr-defined]
    told = [m.text for m in sim.messenger.sent if m.chat.id == "lee"][-1]
    assert "Wang" in told and "locker code" in told and "not someone you named" in told
    assert "stapler:zhang" not in told and "not_a_party" not in told
    assert not sim.world.handovers()


async def test_a_refused_code_after_the_person_answered_something_new_may_go_again(
    office: Office,
) -> None:
    # refused (Wang never answered), then Wang is asked and answers: news, so trying the
    # same code again is a new attempt, not a loop (the guard judges it again)
    to_chen = SendQR(contact="chen", item="lunch:lee", purpose="deposit")
    steps: list[Step] = [
        [to_chen],
        [Inquire(contact="chen", question="Could you take my lunch out of the fridge?"), Wait()],
        [to_chen],
        [Stop(outcome="failed", summary="End of the script.")],
    ]
    stm, _ = await _scripted(office, steps, "bring me my lunch from the fridge")
    tries = [r for r in stm.trace.actions() if r.action == to_chen]  # type: ignore[attr-defined]
    assert len(tries) == 2
    assert tries[0].error == "no_answer" and tries[1].ok
    assert stm.trace.summary == "End of the script."  # type: ignore[attr-defined]


async def test_a_guard_refusal_tells_the_reasoner_not_to_send_it_again(office: Office) -> None:
    to_wang = SendQR(contact="wang", item="stapler:zhang", purpose="collect")
    reasoner = ScriptedReasoner([[to_wang], [Stop(outcome="failed", summary="Giving up.")]])
    sim = SimOffice(office)
    assistant = sim_assistant(sim, lambda: reasoner, reasoner_name="scripted")
    stm = await run_one(sim, assistant, "lee", "bring me Zhang's stapler")
    assert any("Do not send it again unchanged" in f for f in reasoner.seen_feedback[1])
    assert stm.trace.outcome == "failed" and stm.trace.summary.startswith("Giving up.")


async def test_the_requesters_own_item_is_called_theirs(office: Office) -> None:
    to_wang = SendQR(contact="wang", item="document:lee", purpose="sign")
    asked: Step = [Inquire(contact="wang", question="Could you sign it?"), Wait()]
    _, sim = await _scripted(office, [asked, [to_wang], [to_wang]], "sign my document")
    told = [m.text for m in sim.messenger.sent if m.chat.id == "lee"][-1]
    assert "for your document" in told and "Lee Ming's" not in told
