"""Only the model's mistakes are fed back to it: ModelOutputError is retried with its text,
any other exception raised while checking an answer is a bug of ours and surfaces at once.

Each reasoner that asks a model for typed output (the LLM agents, the hybrid's reader, the
baselines) gets a bad answer that is repaired, and a bug injected into its own checks that
must reach the caller after one request, its text never sent to the model.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from typing import Any, NoReturn

import pytest

from assistantx.adapters.model import OpenAICompatibleModel
from assistantx.agents import baselines, hybrid
from assistantx.agents.base import AgentContext
from assistantx.agents.baselines import BaselineFactory
from assistantx.agents.llm import build_factory
from assistantx.core.actions import Inform, Wait
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
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import Reply, ScriptedLLM
from helpers.eventually import eventually
from helpers.llm_office import decision, llm_model, llm_settings

PLAN = Plan(goal="get Lee a stapler", subgoals=[SubGoal(description="ask an owner")])
BUG = "our own check broke here"


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def context(office: Office, text: str = "get me a stapler") -> AgentContext:
    trace = Trace(instruction_id="ins-9", requester="lee", text=text, reasoner="llm", started_at=0)
    trace.steps.append(TraceStep(index=0, started_at=0.0))
    stm = ShortTermMemory(instruction_id="ins-9", requester="lee", text=text, trace=trace)
    return AgentContext(
        ltm=LongTermMemory(office), stm=stm, resolver=Resolver(office), step=0, now=0.0
    )


def raising(error: type[Exception]) -> Callable[..., NoReturn]:
    def broken(*args: Any, **kwargs: Any) -> NoReturn:
        raise error(BUG)

    return broken


def sent_to_model(llm: ScriptedLLM) -> str:
    return "\n".join(r.last_user_text for r in llm.requests)


# -- the LLM agents ------------------------------------------------------------------------


async def test_a_decision_naming_an_unknown_person_is_retried_with_the_reason(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    scripted_llm.script(
        "decision",
        decision(Inform(contact="Mr Nobody", content="hello")),
        decision(Inform(contact="zhang", content="hello")),
    )
    factory = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))
    reasoner = factory()
    made = await reasoner.decide(context(office), Percept(), PLAN)
    await reasoner.stop()

    assert made.actions[0].contact == "zhang"  # type: ignore[union-attr]
    retry = scripted_llm.requests[1].last_user_text
    assert "It could not be used: actions[0] (inform): Unknown contact 'Mr Nobody'" in retry


@pytest.mark.parametrize("error", [KeyError, TypeError, AttributeError, ValueError])
async def test_a_bug_in_the_decision_check_surfaces_and_is_never_fed_back(
    error: type[Exception],
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(Resolver, "ground", raising(error))
    scripted_llm.script("decision", decision(Inform(contact="zhang", content="hello")))
    factory = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))
    reasoner = factory()
    with pytest.raises(error, match=BUG):
        await reasoner.decide(context(office), Percept(), PLAN)
    await reasoner.stop()

    assert len(scripted_llm.requests) == 1  # no repair request was made
    assert BUG not in sent_to_model(scripted_llm)


async def test_a_bug_in_the_perception_check_surfaces(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(Resolver, "person", raising(ValueError))
    scripted_llm.script("perception", {"people": ["zhang"], "summary": "x"})
    reasoner = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))()
    with pytest.raises(ValueError, match=BUG):
        await reasoner.perceive(context(office))
    await reasoner.stop()
    assert len(scripted_llm.requests) == 1


async def test_a_bug_in_the_reflection_check_surfaces(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(Resolver, "ground_update", raising(KeyError))
    update = {"kind": "availability", "person": "zhang", "available": False, "evidence": "silent"}
    scripted_llm.script("reflection", {"verdict": "N", "reason": "no answer", "updates": [update]})
    reasoner = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))()
    ctx = context(office)
    with pytest.raises(KeyError, match=BUG):
        await reasoner.reflect(
            ctx, Percept(), PLAN, Decision(actions=[Wait(reason="reply")]), [], Observation()
        )
    await reasoner.stop()
    assert len(scripted_llm.requests) == 1


# -- the hybrid's reader -------------------------------------------------------------------


def _hybrid(office: Office, llm: ScriptedLLM) -> hybrid.HybridReasoner:
    factory = hybrid.build_factory(office, llm_settings(llm), model=llm_model(llm))
    reasoner = factory()
    assert isinstance(reasoner, hybrid.HybridReasoner)
    return reasoner


async def test_the_hybrid_reader_retries_a_name_outside_memory_with_the_reason(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    made_up = {"sure": True, "tasks": [{"kind": "transfer", "item": "stapler", "owner": "Qqq"}]}
    good = {"sure": True, "tasks": [{"kind": "transfer", "item": "stapler", "owner": "Zhang"}]}
    scripted_llm.script("understanding", made_up, good)
    reasoner = _hybrid(office, scripted_llm)
    frame = await reasoner.read(context(office, "get me the stapler of Zhang"), [])
    await reasoner.stop()

    assert frame.question is None and frame.tasks[0].owner == "zhang"
    assert "I did not understand 'Qqq'" in scripted_llm.requests[1].last_user_text


async def test_a_bug_in_the_hybrid_mapping_surfaces_and_is_never_fed_back(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(hybrid, "to_task_frame", raising(ValueError))
    good = {"sure": True, "tasks": [{"kind": "transfer", "item": "stapler", "owner": "Zhang"}]}
    scripted_llm.script("understanding", good)
    reasoner = _hybrid(office, scripted_llm)
    with pytest.raises(ValueError, match=BUG):
        await reasoner.read(context(office), [])
    await reasoner.stop()
    assert len(scripted_llm.requests) == 1


# -- the baselines -------------------------------------------------------------------------


def _react(llm: ScriptedLLM) -> baselines.BaselineReasoner:
    return BaselineFactory("react", OpenAICompatibleModel(llm.base_url, "scripted"))()


async def test_a_baseline_answer_with_two_actions_is_retried_with_the_rule(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    hello = Inform(contact="zhang", content="hello")
    scripted_llm.script("react", decision(hello, hello), decision(hello))
    reasoner = _react(scripted_llm)
    made = await reasoner.decide(context(office), Percept(), PLAN)
    await reasoner.stop()
    assert len(made.actions) == 1
    assert "give exactly one action per turn" in scripted_llm.requests[1].last_user_text


async def test_a_bug_in_a_baseline_check_surfaces_and_is_never_fed_back(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(baselines, "check_actions", raising(ValueError))
    scripted_llm.script("react", decision(Inform(contact="zhang", content="hello")))
    reasoner = _react(scripted_llm)
    with pytest.raises(ValueError, match=BUG):
        await reasoner.decide(context(office), Percept(), PLAN)
    await reasoner.stop()
    assert len(scripted_llm.requests) == 1
    assert BUG not in sent_to_model(scripted_llm)


async def test_a_call_cut_off_by_the_instructions_time_limit_is_still_counted(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    scripted_llm.script("perception", Reply(content="{}", delay_s=30))
    reasoner = build_factory(office, llm_settings(scripted_llm), model=llm_model(scripted_llm))()
    ctx = context(office)
    call = asyncio.create_task(reasoner.perceive(ctx))
    await eventually(lambda: scripted_llm.requests, what="the request reached the server")
    call.cancel()
    with pytest.raises(asyncio.CancelledError):
        await call
    await reasoner.stop()
    assert [(c.agent, c.attempts, c.estimated) for c in ctx.calls] == [("perception", 1, True)]
