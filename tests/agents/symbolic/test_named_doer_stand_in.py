"""A named doer who is out is said, and another who may do it is asked for only on the
requester's yes (``agents.symbolic.stand_in``): "can Omar fix my book?" where Omar keeps the
mending bench with Nell, and Omar never answers, asks "Omar Vance isn't available. Shall I
ask Nell Oduya instead?"; a yes goes on with Nell, a no (or the requester's silence) ends the
request, saying so, and nobody else is asked. A signature is the named signer's own: nobody
stands in for them. The simulated requester whose goal names no doer takes the offer
(``sim.able_doers``)."""

from __future__ import annotations

from typing import Any

import pytest
from _offices import office

from assistantx.agents.symbolic import build_factory
from assistantx.agents.symbolic.roles import Role, RoleState
from assistantx.agents.symbolic.stand_in import question
from assistantx.core.office import Office
from assistantx.core.settings import Settings
from assistantx.core.trace import Trace
from assistantx.sim.requester import Wish, answer
from assistantx.sim.run import run_in_sim
from helpers.mending_room import mending_room

Goal = list[dict[str, Any]]


def _office(name: str) -> Office:
    return mending_room() if name == "mending" else office(name)


async def _run(
    place: Office, who: str, text: str, away: tuple[str, ...], goal: Goal | None
) -> Trace:
    wish = None if goal is None else Wish.from_goal(place, who, [*goal, {"informed": who}])
    run = await run_in_sim(
        place, who, text, build_factory(place, Settings()), unavailable=away, wish=wish
    )
    return run.trace


def _asked(trace: Trace) -> list[tuple[str, str]]:
    return [
        (r.action.contact, r.action.question)
        for r in trace.actions()
        if r.action.type == "inquire" and not r.refused
    ]


# (office, requester, text, who is away, the requester's goal, the question, who stands in)
_CASES = [
    # the class's analogue, in a small office of its own words: a bench with two keepers
    (
        "mending",
        "rosa",
        "the spine of my book came off again, can Omar fix it",
        ("omar",),
        [{"heated": "book:rosa"}, {"holds": ["rosa", "book:rosa"]}],
        "Omar Vance isn't available. Shall I ask Nell Oduya instead?",
        "nell",
    ),
    # other services, people and offices
    (
        "default",
        "lee",
        "my lunch is cold, can Yang Lei heat it?",
        ("yang",),
        [{"heated": "lunch:lee"}, {"holds": ["lee", "lunch:lee"]}],
        "Yang Lei isn't available. Shall I ask Hu Jing instead?",
        "hu",
    ),
    (
        "harbour",
        "may",
        "can June print my file?",
        ("june",),
        [{"printed": "file:may"}, {"holds": ["may", "printout:may"]}],
        "June Park isn't available. Shall I ask Ray Castillo instead?",
        "ray",
    ),
    (
        "default",
        "lee",
        "could Gao Min make me a coffee?",
        ("gao",),
        [{"holds": ["lee", "coffee:lee"]}],
        "Gao Min isn't available. Shall I ask Sun Li instead?",
        "sun",
    ),
    # a stamper: another who owns the seal, as far as the assistant knows (the office's data)
    (
        "default",
        "lee",
        "could Mao Jun stamp my contract with the seal?",
        ("mao",),
        [{"sealed": "document:lee"}, {"holds": ["lee", "document:lee"]}],
        "Mao Jun isn't available. Shall I ask Wang Fang instead?",
        "wang",
    ),
]


@pytest.mark.parametrize(("name", "who", "text", "away", "goal", "said", "other"), _CASES)
async def test_out_doer_is_said_and_another_asked_on_a_yes(
    name: str, who: str, text: str, away: tuple[str, ...], goal: Goal, said: str, other: str
) -> None:
    trace = await _run(_office(name), who, text, away, goal)
    asked = _asked(trace)
    assert (who, said) in asked, asked
    # the named one first, then the requester, then the one standing in
    people = [p for p, _ in asked]
    assert people.index(away[0]) < people.index(who) < people.index(other), asked
    assert trace.outcome == "done", trace.outcome


@pytest.mark.parametrize(("name", "who", "text", "away", "goal", "said", "other"), _CASES[:3])
async def test_on_a_no_nobody_else_is_asked(
    name: str, who: str, text: str, away: tuple[str, ...], goal: Goal, said: str, other: str
) -> None:
    """Without a goal the simulated requester answers from their words alone: they named the
    doer, so "No, thanks." (a yes would be a guess); the request ends and says why."""
    del goal
    trace = await _run(_office(name), who, text, away, None)
    asked = _asked(trace)
    assert (who, said) in asked, asked
    assert other not in [p for p, _ in asked], asked
    assert trace.outcome == "unachievable"
    assert "you did not want anyone else asked" in (trace.summary or "")


async def test_must_not_change_a_named_signer_has_no_stand_in() -> None:
    """A signature is the signer's own: the requester is not offered anyone else."""
    trace = await _run(
        office("default"),
        "lee",
        "Get Zhang Wei to sign my contract.",
        ("zhang",),
        [{"signed": ["document:lee", "zhang"]}, {"holds": ["lee", "document:lee"]}],
    )
    assert [p for p, _ in _asked(trace)] == ["zhang"], _asked(trace)
    assert trace.outcome == "unachievable"


async def test_must_not_change_a_named_doer_who_is_in_does_it() -> None:
    trace = await _run(
        mending_room(),
        "rosa",
        "the spine of my book came off again, can Omar fix it",
        (),
        [{"heated": "book:rosa"}, {"holds": ["rosa", "book:rosa"]}],
    )
    assert [p for p, _ in _asked(trace)] == ["omar"], _asked(trace)
    assert trace.outcome == "done"


def test_a_no_from_the_named_one_is_said_as_such() -> None:
    place = mending_room()
    role = Role("0.heater", "heat", "rosa", fixed="omar", facility="mending_bench")
    state = RoleState(role, "exhausted", excluded={"omar": "said no"})
    assert question(place, state, ["nell"], "mend the book") == (
        "Omar Vance can't do it. Shall I ask Nell Oduya instead?"
    )
    assert question(place, state, ["nell", "ivo"], "mend the book") == (
        "Omar Vance can't do it. Shall I ask someone else who can mend the book instead?"
    )


def test_the_simulated_requester_takes_a_stand_in_only_for_work_of_nobody_named() -> None:
    place = office("default")
    heat = Wish.from_goal(place, "lee", [{"heated": "lunch:lee"}, {"holds": ["lee", "lunch:lee"]}])
    offer = "Yang Lei isn't available. Shall I ask Hu Jing instead?"
    assert answer(place, heat, offer) == "Yes, please."
    # must not change: a signer they named, a thing of someone's, work for another person
    sign = Wish.from_goal(place, "lee", [{"signed": ["document:lee", "zhang"]}])
    assert answer(place, sign, "Zhang Wei isn't available. Shall I ask Mao Jun instead?") == (
        "No, thanks."
    )
    fetch = Wish.from_goal(place, "lee", [{"holds": ["lee", "stapler:wang"]}])
    assert answer(place, fetch, "Wang Fang isn't available. Shall I ask Hu Jing instead?") == (
        "No, thanks."
    )
    printed = Wish.from_goal(
        place, "lee", [{"printed": "file:lee"}, {"holds": ["lee", "printout:lee"]}]
    )
    assert answer(place, printed, "Shall I print your file for Xu Qiang?") == "No, thanks."
