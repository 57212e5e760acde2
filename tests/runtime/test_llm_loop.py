"""The whole PPDR loop with the LLM agents, over real HTTP to the scripted OpenAI server, in
the simulated office: the three levels, repairs of bad output, the loop's refusals, limits,
rate limits, two instructions at once and the accounting in the trace."""

from __future__ import annotations

import asyncio
import json
from typing import Any

import pytest

from assistantx.agents.llm import build_factory
from assistantx.core.actions import Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.office import Office, load_office
from assistantx.sim.office import SimOffice
from fakes.fixtures import scripted_llm  # noqa: F401
from fakes.scripted_llm import RecordedRequest, ScriptedLLM, malformed_json, rate_limited
from helpers.llm_office import (
    CANONICAL_FETCH,
    decision,
    llm_model,
    llm_settings,
    make_assistant,
    people_rows,
    run_llm,
    script_helpers,
    section,
)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@pytest.fixture
def llm(scripted_llm: ScriptedLLM) -> ScriptedLLM:  # noqa: F811
    script_helpers(scripted_llm)
    return scripted_llm


def fetch_from(owner: str, item: str, requester: str = "lee") -> list[dict[str, Any]]:
    """The canonical fetch after the owner's "yes": deposit there, collect at the requester."""
    return [
        decision(
            Move(place=owner),
            SendQR(contact=owner, item=item, purpose="deposit"),
            WaitInPlace(person=owner),
        ),
        decision(
            Move(place=requester),
            SendQR(contact=requester, item=item, purpose="collect"),
            WaitInPlace(person=requester),
        ),
        decision(Stop(outcome="done", summary=f"{item} is with you.")),
    ]


def ask(person: str, question: str) -> dict[str, Any]:
    return decision(Inquire(contact=person, question=question), Wait(timeout_s=60))


# -- the three levels --------------------------------------------------------------------


async def test_l1_fetch_follows_the_canonical_sequence(office: Office, llm: ScriptedLLM) -> None:
    llm.script(
        "decision",
        ask("zhang", "Could you lend Lee your stapler? The robot will come to pick it up."),
        *fetch_from("zhang", "stapler:zhang"),
    )
    run = await run_llm(office, llm, "bring me Zhang's stapler")

    assert run.stm.trace.outcome == "done"
    assert run.action_types() == CANONICAL_FETCH
    assert all(r.ok for r in run.stm.trace.actions())
    assert run.sim.world.check({"holds": ["lee", "stapler:zhang"]})
    assert run.sim.world.check({"informed": "lee"})
    assert run.sim.messenger.sent[-1].text.startswith("[done]")
    # every agent ran once per step, each over HTTP, all answered
    steps = len(run.stm.trace.steps)
    for agent in ("perception", "planning", "decision", "reflection"):
        expected = steps if agent != "reflection" else steps - 1  # no reflection after stop
        assert len(llm.requests_for(agent)) == expected
    assert llm.unscripted == 0 and llm.pending() == 0
    # the shared model was opened for the instruction and closed after it
    assert run.factory.shared.users == 0 and not run.factory.model.started


async def test_l2_unavailable_owner_marked_with_evidence_then_alternative(
    office: Office, llm: ScriptedLLM
) -> None:
    def pick_known_owner(request: RecordedRequest) -> dict[str, Any]:
        # What a model does with the memory it is shown: the nearest known stapler owner
        # that memory does not mark unavailable.
        rows = people_rows(request.last_user_text)
        assert rows["zhang"][2] == "unavailable"
        owner = next(
            p
            for p, (_, _, availability, items, _) in rows.items()
            if "stapler" in items.split(",") and availability != "unavailable"
        )
        return ask(owner, f"Could you lend Lee your stapler, {owner}?")

    llm.script(
        "decision",
        ask("zhang", "Could you lend Lee your stapler?"),
        pick_known_owner,
        *fetch_from("wang", "stapler:wang"),
    )
    run = await run_llm(office, llm, "get me a stapler", unavailable=("zhang",))

    assert run.stm.trace.outcome == "done"
    first = run.stm.trace.steps[0]
    assert first.reflection is not None and first.reflection.verdict == "N"
    assert run.assistant.ltm.availability("zhang") == "unavailable"
    evidence = [
        u.update.evidence
        for u in run.assistant.ltm.updates
        if u.update.kind == "availability" and u.update.person == "zhang"
    ]
    assert evidence and "no reply" in evidence[0]
    second = run.stm.trace.steps[1].results[0].action
    assert isinstance(second, Inquire) and second.contact == "wang"
    assert run.sim.world.check({"holds": ["lee", "stapler:wang"]})
    assert not any(m.chat.id == "zhang" for m in run.sim.messenger.sent[1:])


async def test_l3_group_chat_finds_an_unknown_owner(office: Office, llm: ScriptedLLM) -> None:
    assert load_office().person("lin")  # lin owns scissors, which memory does not know

    def use_the_helper(request: RecordedRequest) -> dict[str, Any]:
        rows = people_rows(request.last_user_text)
        owners = {p: row[2] for p, row in rows.items() if "scissors" in row[3].split(",")}
        assert owners == {"sun": "unavailable", "chen": "unavailable", "lin": "available"}
        return fetch_from("lin", "scissors:lin")[0]

    llm.script(
        "decision",
        ask("sun", "Could you lend Lee your scissors?"),
        ask("chen", "Could you lend Lee your scissors?"),
        decision(
            Inquire(contact="Office Work", question="Does anyone have scissors to lend Lee?"),
            Wait(timeout_s=120),
        ),
        # a yes in the group is not the owner's own yes: the consent guard wants it in her DM
        ask("lin", "Could you lend Lee your scissors?"),
        use_the_helper,
        *fetch_from("lin", "scissors:lin")[1:],
    )
    run = await run_llm(office, llm, "get me some scissors", unavailable=("sun", "chen"))

    assert run.stm.trace.outcome == "done"
    ltm = run.assistant.ltm
    assert ltm.availability("sun") == ltm.availability("chen") == "unavailable"
    assert ltm.ownership("lin", "scissors") is True
    learned = [u for u in ltm.updates if u.update.kind == "ownership"]
    assert learned and "office_work" in learned[0].update.evidence
    assert run.sim.world.check({"holds": ["lee", "scissors:lin"]})


async def test_l3_unachievable_stops_and_tells_the_requester(
    office: Office, llm: ScriptedLLM
) -> None:
    def give_up(request: RecordedRequest) -> dict[str, Any]:
        text = request.last_user_text
        rows = people_rows(text)
        assert rows["sun"][2] == rows["chen"][2] == "unavailable"
        assert "no reply within 120 s" in section(text, "MEMORY")
        return decision(
            Stop(
                outcome="unachievable",
                summary="Nobody could lend you scissors: sun and chen did not answer and "
                "nobody in Office Work offered any.",
            )
        )

    llm.script(
        "decision",
        ask("sun", "Could you lend Lee your scissors?"),
        ask("chen", "Could you lend Lee your scissors?"),
        decision(
            Inquire(contact="office_work", question="Does anyone have scissors to lend Lee?"),
            Wait(timeout_s=120),
        ),
        give_up,
    )
    run = await run_llm(office, llm, "get me some scissors", unavailable=("sun", "chen", "lin"))

    assert run.stm.trace.outcome == "unachievable"
    last = run.sim.messenger.sent[-1]
    assert last.chat.id == "lee" and last.text.startswith("[unachievable] Nobody could")
    assert not run.sim.world.handovers()


# -- bad output and refusals -------------------------------------------------------------


async def test_malformed_output_is_repaired_by_a_retry(office: Office, llm: ScriptedLLM) -> None:
    llm.script(
        "decision",
        malformed_json(),
        decision(Stop(outcome="done", summary="Nothing needed doing.")),
    )
    run = await run_llm(office, llm, "say hello")

    assert run.stm.trace.outcome == "done"
    bad, retry = llm.requests_for("decision")
    # the original conversation and one repair turn quoting the start of the bad answer
    assert retry.messages[:-1] == bad.messages
    feedback = retry.last_user_text
    assert feedback.startswith("Your previous answer began: " + malformed_json().content.strip())
    assert "It could not be used: the answer was cut off at the length limit" in feedback
    assert "JSON" in feedback
    call = next(c for c in run.stm.trace.steps[0].calls if c.agent == "decision")
    assert call.attempts == 2


async def test_unknown_person_is_refused_at_validation_and_corrected(
    office: Office, llm: ScriptedLLM
) -> None:
    llm.script(
        "decision",
        ask("Zhangg Wie Wu", "Could you lend Lee your stapler?"),
        ask("Zhang Wei", "Could you lend Lee your stapler?"),
        decision(Stop(outcome="done", summary="Zhang has been asked.")),
    )
    run = await run_llm(office, llm, "ask Zhang about his stapler")

    first_try, corrected = llm.requests_for("decision")[:2]
    assert corrected.messages[:-1] == first_try.messages
    assert "Zhangg Wie Wu" in corrected.last_user_text  # an excerpt of the rejected answer
    assert "actions[0] (inquire): Unknown contact 'Zhangg Wie Wu'" in corrected.last_user_text
    assert "Did you mean" in corrected.last_user_text
    executed = run.stm.trace.actions()
    assert not any(r.refused for r in executed)  # caught before anything ran
    assert isinstance(executed[0].action, Inquire) and executed[0].action.contact == "zhang"
    assert {m.chat.id for m in run.sim.messenger.sent} == {"zhang", "lee"}


async def test_repeated_action_is_refused_by_the_loop_and_fed_back(
    office: Office, llm: ScriptedLLM
) -> None:
    hello = Inform(contact="zhang", content="The robot will pass by your desk.")
    llm.script(
        "decision",
        decision(hello),
        decision(hello),
        decision(Stop(outcome="failed", summary="I could not do it.")),
    )
    run = await run_llm(office, llm, "tell Zhang the robot is coming")

    repeated = run.stm.trace.steps[1].results[0]
    assert repeated.refused and "no new information" in repeated.observation
    third = llm.requests_for("decision")[2].last_user_text
    assert "repeats an earlier action" in section(
        third, "FEEDBACK FROM THE LAST STEP (refused or failed actions)"
    )
    assert sum(1 for m in run.sim.messenger.sent if m.chat.id == "zhang") == 1


async def test_step_limit_ends_and_tells_the_requester(office: Office, llm: ScriptedLLM) -> None:
    llm.respond_with(lambda r: decision(Wait(reason="thinking", timeout_s=5)), "decision")
    run = await run_llm(office, llm, "do something vague", max_steps=3)

    assert run.stm.trace.outcome == "failed"
    assert "3 steps" in (run.stm.trace.summary or "")
    last = run.sim.messenger.sent[-1]
    assert last.chat.id == "lee" and "3 steps" in last.text
    assert len(llm.requests_for("decision")) == 3


async def test_a_429_storm_is_survived(office: Office, llm: ScriptedLLM) -> None:
    for agent in ("perception", "planning", "decision", "reflection"):
        llm.script(agent, *(rate_limited(0) for _ in range(3)))
    llm.script(
        "decision",
        ask("zhang", "Could you lend Lee your stapler?"),
        *fetch_from("zhang", "stapler:zhang"),
    )
    run = await run_llm(office, llm, "bring me Zhang's stapler")

    assert run.stm.trace.outcome == "done"
    assert sum(1 for r in llm.requests if r.status == 429) == 12
    assert run.sim.world.check({"holds": ["lee", "stapler:zhang"]})


# -- concurrency and accounting ----------------------------------------------------------


async def test_two_instructions_share_the_robot_without_interleaving(
    office: Office, llm: ScriptedLLM
) -> None:
    def plan_for(person: str) -> list[dict[str, Any]]:
        return [
            decision(Inform(contact=person, content="The robot is coming."), Move(place=person)),
            decision(Move(place="printer")),
            decision(Stop(outcome="done", summary="Done.")),
        ]

    scripts = {"ins-1": plan_for("zhang"), "ins-2": plan_for("wang")}

    def by_instruction(request: RecordedRequest) -> dict[str, Any]:
        instruction = request.last_user_text.split("INSTRUCTION ", 1)[1].split(" ", 1)[0]
        return scripts[instruction].pop(0)

    llm.respond_with(by_instruction, "decision")
    sim = SimOffice(office)
    factory = build_factory(office, llm_settings(llm), model=llm_model(llm))
    assistant = make_assistant(office, sim, factory)
    await assistant.start()
    try:
        a = await assistant.submit(
            "lee", "tell Zhang the robot comes, then go to the printer", instruction_id="ins-1"
        )
        b = await assistant.submit(
            "chen", "tell Wang the robot comes, then go to the printer", instruction_id="ins-2"
        )
        await asyncio.gather(assistant.wait(a.instruction_id), assistant.wait(b.instruction_id))
    finally:
        await assistant.stop()

    assert a.trace.outcome == b.trace.outcome == "done"
    arrivals = [e.detail["place"] for e in sim.world.log if e.kind == "robot_arrived"]
    zhang_first = ["desk_04", "print_room", "desk_06", "print_room"]
    wang_first = ["desk_06", "print_room", "desk_04", "print_room"]
    assert arrivals in (zhang_first, wang_first)
    assert any(s.queue for s in (*a.trace.steps, *b.trace.steps))
    assert scripts == {"ins-1": [], "ins-2": []}
    assert factory.shared.users == 0 and not factory.model.started


async def test_token_and_latency_accounting_in_the_trace_json(
    office: Office, llm: ScriptedLLM
) -> None:
    llm.script(
        "decision",
        malformed_json(),
        ask("zhang", "Could you lend Lee your stapler?"),
        decision(Stop(outcome="done", summary="Asked.")),
    )
    run = await run_llm(office, llm, "ask Zhang about the stapler")
    data = json.loads(run.stm.trace.model_dump_json())

    calls = [c for step in data["steps"] for c in step["calls"]]
    assert {c["agent"] for c in calls} == {"perception", "planning", "decision", "reflection"}
    for c in calls:
        assert c["model"] == "scripted-model"
        assert c["prompt_tokens"] > 0 and c["completion_tokens"] > 0
        assert c["latency_s"] > 0 and c["estimated"] is False
    assert [c["attempts"] for c in calls if c["agent"] == "decision"] == [2, 1]
    usage = data["usage"]
    assert usage["calls"] == len(calls) == len(llm.requests) - 1  # one call had two attempts
    # the totals are what the server reported, request by request (whitespace tokens)
    served = [r for r in llm.requests if r.status == 200]
    prompt_tokens = sum(len(str(m["content"]).split()) for r in served for m in r.messages)
    assert usage["prompt_tokens"] == prompt_tokens == sum(c["prompt_tokens"] for c in calls)
    assert usage["completion_tokens"] == sum(c["completion_tokens"] for c in calls)
    assert usage["latency_s"] == pytest.approx(sum(c["latency_s"] for c in calls))
    assert usage["by_agent"]["decision"]["calls"] == 2
