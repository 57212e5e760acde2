"""Every kind of instruction, L1/L2/L3 and unachievable, end to end in the simulated office.

Each case runs the Assistant with the symbolic reasoner against SimOffice and checks the
world's truth: the goal milestones, that the requester was told, that nothing reached the
wrong person, and for L1 the canonical number of actions of docs/task-semantics.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Office


@dataclass(frozen=True)
class Case:
    name: str
    text: str
    goal: list[dict[str, Any]]
    unavailable: tuple[str, ...] = ()
    outcome: str = "done"
    actions: int | None = None  # the canonical count, for L1
    requester: str = "lee"
    helpers: tuple[str, ...] = field(default=())  # who should have helped (L2/L3)


CASES = [
    # fetch, any owner: nearest known owner, then the next, then the group chat
    Case("fetch L1", "bring me a stapler", [{"holds": ["lee", "stapler:*"]}], actions=9),
    Case(
        "fetch L2",
        "Could you get me a stapler?",
        [{"holds": ["lee", "stapler:zhang"]}],
        ("wang",),
        actions=11,
    ),
    Case("fetch L3", "I need a stapler", [{"holds": ["lee", "stapler:hu"]}], ("wang", "zhang")),
    Case(
        "fetch L3 unachievable",
        "bring me a stapler",
        [],
        ("wang", "zhang", "hu", "gao"),
        outcome="unachievable",
    ),
    # fetch from a named owner
    # 10: the requester is told first that Yang will be asked (an inform), then as before
    Case("fetch named L1", "bring me Yang's book", [{"holds": ["lee", "book:yang"]}], actions=10),
    Case("fetch named away", "bring me Yang's book", [], ("yang",), outcome="unachievable"),
    # deliver
    Case("deliver L1", "take my book to Wang", [{"holds": ["wang", "book:lee"]}], actions=9),
    Case("deliver away", "take my book to Wang", [], ("wang",), outcome="unachievable"),
    # print: the two printer guards, then nobody
    Case(
        "print L1",
        "print my file and bring it to me",
        [{"printed": "file:lee"}, {"holds": ["lee", "printout:lee"]}],
        actions=10,
    ),
    Case(
        "print L2",
        "please print my slides",
        [{"printed": "file:lee"}, {"holds": ["lee", "printout:lee"]}],
        ("mao",),
        actions=12,
    ),
    Case("print unachievable", "print my file", [], ("mao", "xu"), outcome="unachievable"),
    # copy
    Case(
        "copy L1",
        "make a copy of my contract",
        [
            {"copied": "document:lee"},
            {"holds": ["lee", "copy:lee"]},
            {"holds": ["lee", "document:lee"]},
        ],
        actions=13,
    ),
    Case(
        "copy L2",
        "photocopy my contract",
        [{"copied": "document:lee"}, {"holds": ["lee", "copy:lee"]}],
        ("mao",),
    ),
    # sign: only the named signer will do
    Case(
        "sign L1",
        "get Zhang to sign my contract",
        [{"signed": ["document:lee", "zhang"]}, {"holds": ["lee", "document:lee"]}],
        actions=12,
    ),
    Case("sign away", "get Zhang to sign my contract", [], ("zhang",), outcome="unachievable"),
    # seal: known seal owners, then the group finds Sun, whose seal memory did not know
    Case(
        "seal L1",
        "get my contract stamped with the company seal",
        [{"sealed": "document:lee"}, {"holds": ["lee", "document:lee"]}],
        actions=12,
    ),
    Case(
        "seal L2",
        "get my contract stamped with the company seal",
        [{"sealed": "document:lee"}, {"holds": ["lee", "document:lee"]}],
        ("wang",),
    ),
    Case(
        "seal L3",
        "my invoice needs the official seal",
        [{"sealed": "document:lee"}, {"holds": ["lee", "document:lee"]}],
        ("wang", "mao"),
    ),
    Case(
        "seal L3 unachievable",
        "get my contract stamped with the company seal",
        [],
        ("wang", "mao", "sun"),
        outcome="unachievable",
    ),
    # coffee, water, vending
    Case("coffee L1", "make me a coffee", [{"holds": ["lee", "coffee:lee"]}], actions=9),
    Case("coffee L2", "I'd love a latte", [{"holds": ["lee", "coffee:lee"]}], ("gao",), actions=11),
    Case("coffee unachievable", "make me a coffee", [], ("gao", "sun"), outcome="unachievable"),
    Case("water L1", "grab me a glass of water", [{"holds": ["lee", "water:lee"]}], actions=9),
    Case(
        "vend L1",
        "buy me a soda from the vending machine",
        [{"holds": ["lee", "snack:lee"]}],
        actions=9,
    ),
    # heat: fridge guard, then microwave guard
    Case(
        "heat L1",
        "heat up my lunch",
        [{"heated": "lunch:lee"}, {"holds": ["lee", "lunch:lee"]}],
        actions=14,
    ),
    Case(
        "heat L2",
        "warm up my leftovers",
        [{"heated": "lunch:lee"}, {"holds": ["lee", "lunch:lee"]}],
        ("chen", "hu"),
    ),
    # files
    Case(
        "forward own file",
        "send my slides to Zhou",
        [{"received": ["zhou", "file:lee"]}],
        actions=2,
    ),
    Case(
        "get a file",
        "get Wang's report file for me",
        [{"received": ["lee", "file:wang"]}],
        actions=4,
    ),
    Case("get a file away", "get Wang's report file for me", [], ("wang",), outcome="unachievable"),
    # combinations
    Case(
        "print and deliver",
        "print my file and take it to Wang",
        [{"printed": "file:lee"}, {"holds": ["wang", "printout:lee"]}],
    ),
    Case(
        "two fetches",
        "get me a stapler and a pen",
        [{"holds": ["lee", "stapler:*"]}, {"holds": ["lee", "pen:*"]}],
    ),
    Case(
        "fetch with a time phrase",
        "Please find me a book to read over lunch.",
        [{"holds": ["zhang", "book:*"]}],
        requester="zhang",
        actions=9,
    ),
    Case(
        "a belonging and a product",
        "Bring me a stapler and a coffee, please.",
        [{"holds": ["lee", "stapler:*"]}, {"holds": ["lee", "coffee:lee"]}],
    ),
    Case(
        "three fetches",
        "bring me scissors, a pen and some wipes",
        [
            {"holds": ["lee", "scissors:*"]},
            {"holds": ["lee", "pen:*"]},
            {"holds": ["lee", "wipes:*"]},
        ],
    ),
    Case(
        "heat then coffee",
        "Could you heat up my lunch and then make me a coffee?",
        [
            {"heated": "lunch:lee"},
            {"holds": ["lee", "lunch:lee"]},
            {"holds": ["lee", "coffee:lee"]},
        ],
    ),
]


def _holders(goal: list[dict[str, Any]]) -> set[str]:
    return {m["holds"][0] for m in goal if "holds" in m}


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
async def test_instruction_reaches_its_goal(office: Office, case: Case) -> None:
    run = await run_instruction(office, case.requester, case.text, unavailable=case.unavailable)
    trace = run.stm.trace
    assert trace.outcome == case.outcome, trace.summary
    world = run.sim.world
    for milestone in [*case.goal, {"informed": case.requester}]:
        assert world.check(milestone), f"{milestone} not reached: {trace.summary}"
    # the requester heard the outcome last, with the outcome in the message
    last = run.sim.messenger.sent[-1]
    assert last.chat.id == case.requester and last.text.startswith(f"[{case.outcome}]")
    # nothing was handed to anyone but the locker and the people the goal names
    allowed = {"locker"} | _holders(case.goal) | {case.requester}
    for event in world.handovers():
        assert event.detail["to"] in allowed | {event.detail["frm"]}, event
    # nobody known to be away was asked twice, and no action was refused
    assert not [r for r in trace.actions() if r.refused]
    if case.actions is not None:
        assert len(run.actions) == case.actions, run.actions
    if case.outcome == "unachievable":
        assert not world.handovers()  # no false start: nothing moved
        assert "could not" in (trace.summary or "")


async def test_unachievable_names_who_was_asked(office: Office) -> None:
    run = await run_instruction(
        office, "lee", "bring me a stapler", unavailable=("wang", "zhang", "hu", "gao")
    )
    summary = run.stm.trace.summary or ""
    assert "Wang Fang" in summary and "Zhang Wei" in summary and "Office Work" in summary
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert [a.contact for a in asked] == ["wang", "zhang", "office_work"]  # type: ignore[union-attr]


async def test_group_chat_helper_is_remembered(office: Office) -> None:
    run = await run_instruction(office, "lee", "bring me a stapler", unavailable=("wang", "zhang"))
    ltm = run.assistant.ltm
    assert ltm.ownership("hu", "stapler") is True  # memory did not know before
    assert ltm.availability("wang") == "unavailable"
    assert ltm.availability("zhang") == "unavailable"
    assert ltm.item_holder("stapler:hu") == "lee"


async def test_trace_records_four_agents_with_zero_tokens(office: Office) -> None:
    run = await run_instruction(office, "lee", "make me a coffee")
    step = run.stm.trace.steps[0]
    assert [c.agent for c in step.calls] == ["perception", "planning", "decision", "reflection"]
    assert all(c.prompt_tokens == 0 and c.completion_tokens == 0 for c in step.calls)
    assert all(c.latency_s >= 0 and c.model == "symbolic" for c in step.calls)
    assert step.percept is not None and "gao" in step.percept.people
    assert step.plan is not None and not step.plan.subgoals[0].done


async def test_partly_done_request_says_what_was_and_was_not_done(office: Office) -> None:
    # every stapler owner is away, the coffee machine has Sun: only the coffee can be had
    run = await run_instruction(
        office,
        "lee",
        "Bring me a stapler and a coffee, please.",
        unavailable=("wang", "zhang", "hu", "gao"),
    )
    trace = run.stm.trace
    assert trace.outcome == "unachievable", trace.summary  # never "done" with a task left
    assert run.sim.world.check({"holds": ["lee", "coffee:lee"]})
    assert not run.sim.world.check({"holds": ["lee", "stapler:*"]})
    summary = trace.summary or ""
    done, _, not_done = summary.partition("Not done:")
    assert "coffee" in done and "Sun Li" in done
    assert "stapler" in not_done and "Office Work" in not_done
    assert run.sim.messenger.sent[-1].text == f"[unachievable] {summary}"


async def test_requester_who_never_collects_hears_failed_and_where_things_are(
    office: Office,
) -> None:
    run = await run_instruction(
        office, "lee", "Bring me a stapler and a coffee, please.", unavailable=("lee",)
    )
    trace = run.stm.trace
    assert trace.outcome == "failed", trace.summary
    summary = trace.summary or ""
    assert "Done:" not in summary
    assert "you did not come to the robot" in summary
    # the stapler was put in the locker and never collected: the requester is told so
    assert "Still in the robot's locker: Wang Fang's stapler" in summary
    assert run.sim.world.locker_contents() == ["stapler:wang"]
