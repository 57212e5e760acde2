"""Every reasoner that acts on a model's proposal hands over only what the requester asked
for: the LLM reasoner's and the baselines' locker codes are checked against the requester's
words (the hybrid's readings are, in tests/agents/test_hybrid.py)."""

from __future__ import annotations

import pytest

from assistantx.agents.llm.grounding import UNSURE_QUESTION, RequestWords, ungrounded_action
from assistantx.agents.registry import reasoner_factory
from assistantx.core.actions import Action, ForwardFile, Inquire, SendQR
from assistantx.core.office import Office, load_office
from assistantx.sim.office import SimOffice
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import ScriptedLLM, json_reply
from helpers.llm_office import decision, llm_model, llm_settings, make_assistant, script_helpers
from helpers.office import run_one


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


GROUNDED: list[tuple[str, Action]] = [
    ("bring me Zhang's stapler", SendQR(contact="zhang", item="stapler:zhang", purpose="deposit")),
    ("bring me Zhang's stapler", SendQR(contact="lee", item="stapler:zhang", purpose="collect")),
    # the owner of "a stapler" is found in memory, never named by the requester
    ("I need a stapler", SendQR(contact="wang", item="stapler:wang", purpose="deposit")),
    ("print my report and bring it to me", SendQR(contact="lee", item="printout:lee")),
    (
        "print my report and bring it to me",
        SendQR(contact="lee", item="printout:lee", purpose="produce"),
    ),
    ("Zhang should sign my contract", SendQR(contact="zhang", item="document:lee", purpose="sign")),
    ("send my slides to Zhou", ForwardFile(source="lee", target="zhou", file="file:lee")),
]


@pytest.mark.parametrize(("text", "action"), GROUNDED)
def test_what_the_requester_asked_for_is_grounded(
    office: Office, text: str, action: Action
) -> None:
    assert ungrounded_action(RequestWords(office, [text]), "lee", action) is None


UNGROUNDED: list[tuple[str, Action, str]] = [
    # the prompt's example copied onto another request
    (
        "print my report and bring it to me",
        SendQR(contact="wang", item="stapler:wang", purpose="deposit"),
        "'stapler'",
    ),
    (
        "bring me Zhang's stapler",
        SendQR(contact="wang", item="stapler:zhang", purpose="collect"),
        "Wang Fang",
    ),
    ("bring me my lunch", SendQR(contact="lee", item="lunch:lee", purpose="heat"), "heat"),
    ("bring me my contract", SendQR(contact="zhang", item="document:lee", purpose="sign"), "sign"),
    ("send my slides to Zhou", ForwardFile(source="lee", target="wang", file="file:lee"), "Wang"),
]


@pytest.mark.parametrize(("text", "action", "missing"), UNGROUNDED)
def test_what_the_requester_never_asked_for_is_named(
    office: Office, text: str, action: Action, missing: str
) -> None:
    reason = ungrounded_action(RequestWords(office, [text]), "lee", action)
    assert reason is not None and missing in reason


# the model's decision agent for each reasoner that acts on a model's proposed actions
DECIDERS = {"llm": "decision", "direct": "direct", "cot": "cot", "react": "react"}
INVENTED = decision(SendQR(contact="wang", item="stapler:wang", purpose="deposit"))


@pytest.mark.parametrize("name", sorted(DECIDERS))
async def test_an_invented_task_is_never_acted_on_the_requester_is_asked(
    office: Office,
    scripted_llm: ScriptedLLM,  # noqa: F811
    name: str,
) -> None:
    script_helpers(scripted_llm)
    agent = DECIDERS[name]
    scripted_llm.script(agent, *(json_reply(INVENTED) for _ in range(3)))
    sim = SimOffice(office)
    settings = llm_settings(scripted_llm)
    model = llm_model(scripted_llm)
    factory = reasoner_factory(name, office, settings, model=model)
    assistant = make_assistant(office, sim, factory, max_steps=1)  # type: ignore[arg-type]
    try:
        stm = await run_one(sim, assistant, "lee", "print my report and bring it to me")
    finally:
        await model.stop()

    repairs = scripted_llm.requests_for(agent)
    assert len(repairs) == 3  # fed back twice, then given up
    assert "the request never mentions 'stapler'" in repairs[1].last_user_text
    actions = [r.action for r in stm.trace.actions() if not r.refused]
    assert not [a for a in actions if isinstance(a, SendQR)]  # no code for Wang's stapler
    asked = [a for a in actions if isinstance(a, Inquire)]  # the requester is asked instead
    assert [(a.contact, a.question) for a in asked] == [("lee", UNSURE_QUESTION)]
    assert not sim.world.check({"holds": ["lee", "stapler:wang"]})
    calls = [c for s in stm.trace.steps for c in s.calls if c.agent == agent]
    assert sum(c.attempts for c in calls) == 3
