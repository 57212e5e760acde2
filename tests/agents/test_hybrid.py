"""The hybrid reasoner: the model reads the request (scripted here), the symbolic PPDR acts."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.hybrid import (
    UNSURE_QUESTION,
    HybridFactory,
    build_cascade_factory,
    build_factory,
)
from assistantx.core.actions import Inquire, SendQR
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office, parse_office
from assistantx.memory.short_term import ShortTermMemory
from assistantx.sim.office import SimOffice
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import ScriptedLLM, json_reply
from helpers.llm_office import llm_model, llm_settings, make_assistant
from helpers.yaml_files import raw_yaml


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def _run(
    office: Office, llm: ScriptedLLM, text: str, *, max_steps: int = 20, cascade: bool = False
) -> tuple[ShortTermMemory, SimOffice]:
    sim = SimOffice(office)
    build = build_cascade_factory if cascade else build_factory
    factory = build(office, llm_settings(llm), model=llm_model(llm))
    assert isinstance(factory, HybridFactory)
    assistant = make_assistant(office, sim, factory, max_steps=max_steps)  # type: ignore[arg-type]
    await sim.locker.start()
    await assistant.start()
    try:
        stm = await assistant.submit("lee", text)
        stm = await assistant.wait(stm.instruction_id)
    finally:
        await assistant.stop()
        await sim.locker.stop()
        await factory.model.stop()
    return stm, sim


def _frame(*tasks: dict[str, Any], sure: bool = True) -> dict[str, Any]:
    return {"sure": sure, "tasks": list(tasks)}


async def test_the_model_reads_the_request_and_the_symbolic_ppdr_does_it(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    # wording the rule parser does not know; the model reads it
    scripted_llm.script(
        "understanding",
        json_reply(_frame({"kind": "transfer", "item": "stapler", "owner": "Zhang Wei"})),
    )
    stm, sim = await _run(office, scripted_llm, "yo, that stapler of Zhang Wei, I want it here")

    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"holds": ["lee", "stapler:zhang"]})
    assert len(scripted_llm.requests_for("understanding")) == 1  # read once, not every step
    sent = scripted_llm.requests_for("understanding")[0]
    assert sent.response_format is not None  # structured output, enforced by the server
    calls = [c for s in stm.trace.steps for c in s.calls if c.agent == "understanding"]
    assert len(calls) == 1 and calls[0].llm and calls[0].prompt_tokens > 0
    assert stm.trace.usage.llm_calls == 1
    qr = [r.action for r in stm.trace.actions() if isinstance(r.action, SendQR)]
    assert [a.contact for a in qr] == ["zhang", "lee"]


async def test_an_unsure_reading_becomes_one_question_to_the_requester(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    scripted_llm.script("understanding", json_reply(_frame(sure=False)))
    stm, _ = await _run(office, scripted_llm, "hmm the thing, you know", max_steps=1)

    asked = [r.action for r in stm.trace.actions() if isinstance(r.action, Inquire)]
    assert len(asked) == 1
    assert asked[0].contact == "lee"
    assert asked[0].question == UNSURE_QUESTION


async def test_a_name_outside_memory_is_repaired_or_asked_never_guessed(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    made_up = _frame({"kind": "transfer", "item": "stapler", "owner": "Zhangg Wie Wu"})
    scripted_llm.script("understanding", *(json_reply(made_up) for _ in range(3)))
    stm, _ = await _run(office, scripted_llm, "bring me the stapler of Zhangg Wie Wu", max_steps=1)

    repairs = scripted_llm.requests_for("understanding")
    assert len(repairs) == 3  # the first answer and two repairs
    assert "Zhangg Wie Wu" in repairs[1].last_user_text
    # nobody outside memory was contacted: the one question went to the requester
    assert [r.action.contact for r in stm.trace.actions() if isinstance(r.action, Inquire)] == [
        "lee"
    ]
    calls = [c for s in stm.trace.steps for c in s.calls if c.agent == "understanding"]
    assert sum(c.attempts for c in calls) == 3


async def test_a_reading_of_a_task_never_asked_for_is_never_acted_on(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    # a small model copying its prompt's example: well formed, and about something else
    invented = _frame({"kind": "transfer", "item": "stapler", "owner": "Wang Fang"})
    scripted_llm.script("understanding", *(json_reply(invented) for _ in range(3)))
    stm, sim = await _run(office, scripted_llm, "print my report and bring it to me", max_steps=1)

    repairs = scripted_llm.requests_for("understanding")
    assert len(repairs) == 3  # fed back twice, then given up
    assert "the request never mentions 'Wang Fang'" in repairs[1].last_user_text
    actions = [r.action for r in stm.trace.actions()]
    assert not [a for a in actions if isinstance(a, SendQR)]  # nothing fetched from Wang
    asked = [a for a in actions if isinstance(a, Inquire)]  # the requester is asked instead
    assert [(a.contact, a.question) for a in asked] == [("lee", UNSURE_QUESTION)]
    assert not sim.world.check({"holds": ["lee", "stapler:wang"]})
    calls = [c for s in stm.trace.steps for c in s.calls if c.agent == "understanding"]
    assert sum(c.attempts for c in calls) == 3


async def test_a_reading_in_the_requesters_own_words_is_acted_on(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    # accents, capitals, a plural and a possessive: still the stapler of Zhang Wei
    reading = _frame({"kind": "transfer", "item": "stapler", "owner": "Zhang Wei"})
    scripted_llm.script("understanding", json_reply(reading))
    stm, sim = await _run(office, scripted_llm, "ZHĀNG WEI's STAPLERS, the one, to me pls")

    assert len(scripted_llm.requests_for("understanding")) == 1
    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"holds": ["lee", "stapler:zhang"]})


async def test_the_cascade_costs_no_call_when_the_embedded_reader_is_sure(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    stm, sim = await _run(office, scripted_llm, "bring me Zhang Wei's stapler", cascade=True)

    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"holds": ["lee", "stapler:zhang"]})
    assert scripted_llm.requests == []
    assert stm.trace.usage.llm_calls == 0


async def test_the_cascade_asks_the_model_when_the_embedded_reader_is_unsure(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    scripted_llm.script("understanding", json_reply(_frame(sure=False)))
    stm, _ = await _run(office, scripted_llm, "hmm the thing, you know", max_steps=1, cascade=True)

    assert len(scripted_llm.requests_for("understanding")) == 1
    asked = [r.action for r in stm.trace.actions() if isinstance(r.action, Inquire)]
    assert [(a.contact, a.question) for a in asked] == [("lee", UNSURE_QUESTION)]
    assert stm.trace.usage.llm_calls == 1


async def test_the_cascade_never_sends_a_fax_to_an_answer_that_says_i_dont_know(
    scripted_llm: ScriptedLLM,  # noqa: F811
) -> None:
    # "please fax my document": the embedded reader asks where to; the requester of `run`
    # knows no more than they wrote. Read as the answer, "Sorry, I don't ..." was the place
    # the fax went to; the question stays open, and the model (unsure here) is asked instead
    raw = raw_yaml(DEFAULT_OFFICE)
    raw["operations"].append(
        {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "document", "sends_out": True}
    )
    for f in raw["facilities"]:
        if f["id"] == "printer":
            f["operations"] = [*f["operations"], "fax"]
    fax = parse_office(raw)
    scripted_llm.script("understanding", json_reply(_frame(sure=False)))
    stm, sim = await _run(fax, scripted_llm, "please fax my document", cascade=True)

    assert not sim.world.check({"heated": "document:lee"})
    assert not [r for r in stm.trace.actions() if isinstance(r.action, SendQR)]
    assert len(scripted_llm.requests_for("understanding")) >= 1
    assert stm.trace.outcome != "done", stm.trace.summary
