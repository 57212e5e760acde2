"""A base instruction whose requester guards the facility it needs is a real request ("print
my file" from the printer's own keeper): the loader accepts it, and the oracle's dry run and
its run against the simulated office agree (the dataset generator's verification). When the
requester is the facility's only guard they run it themselves with the robot: nobody is
asked, and everything of theirs is handed over where they work it (the oracle; the embedded
planner, too, asks nobody and forwards nothing, though it still hands the result over at
their desk)."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest

from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.oracle.policy import dry_run
from assistantx.agents.symbolic import build_factory
from assistantx.core.actions import Inquire, Move, SendQR
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office, parse_office
from assistantx.core.settings import Settings
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.sim.office import SimOffice
from helpers.dataset_tasks import verify_every_variant
from helpers.office import run_one, sim_assistant
from helpers.yaml_files import raw_yaml


@functools.cache
def _raw() -> dict[str, Any]:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    return raw


def _only_guard(facility: str, guard: str, lunch: bool = False) -> Office:
    raw = copy.deepcopy(_raw())
    next(f for f in raw["facilities"] if f["id"] == facility)["guards"] = [guard]
    if lunch:
        next(p for p in raw["people"] if p["id"] == guard)["owns"].append({"type": "lunch"})
    return parse_office(raw, f"{facility} run by {guard} alone")


CASES = {
    "printer, its only guard": (
        lambda: _only_guard("printer", "xu"),
        "xu",
        "Print my file and bring the printout to me.",
        Part(kind="print"),
    ),
    "copier, its only guard": (
        lambda: _only_guard("printer", "mao"),
        "mao",
        "Make a photocopy of my contract for me.",
        Part(kind="copy"),
    ),
    "microwave, its only guard": (
        lambda: _only_guard("microwave", "hu", lunch=True),
        "hu",
        "Heat up my lunch and bring it to me.",
        Part(kind="heat"),
    ),
    "coffee machine, its only guard": (
        lambda: _only_guard("coffee_machine", "gao"),
        "gao",
        "Make me a coffee, please.",
        Part(kind="coffee"),
    ),
    "printer, one of its guards": (
        load_office,
        "xu",
        "Print my file and bring the printout to me.",
        Part(kind="print"),
    ),
    "fridge keeper heating their own lunch": (
        load_office,
        "chen",
        "Heat up my lunch and bring it to me.",
        Part(kind="heat"),
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
async def test_the_generators_verification_agrees(case: str) -> None:
    make, requester, text, part = CASES[case]
    office = make()
    base = BaseInstruction(id="g1", requester=requester, text=text, parts=(part,))
    check_base(base, office)  # accepted
    await verify_every_variant(office, base)


def test_the_only_guard_runs_it_with_the_robot_at_the_facility() -> None:
    office = _only_guard("printer", "xu")
    base = BaseInstruction(
        id="g1", requester="xu", text="Print my file, please.", parts=(Part(kind="print"),)
    )
    run = dry_run(base, build_plan(base, office), office, set())
    assert not [a for a in run.actions if isinstance(a, Inquire)]
    assert [a.place for a in run.actions if isinstance(a, Move)] == ["printer"]
    assert [(a.contact, a.purpose) for a in run.actions if isinstance(a, SendQR)] == [
        ("xu", "produce"),
        ("xu", "collect"),
    ]
    assert run.outcome == "done"


def test_a_facility_nobody_runs_is_still_refused() -> None:
    raw = copy.deepcopy(_raw())
    next(f for f in raw["facilities"] if f["id"] == "printer")["guards"] = []
    office = parse_office(raw)
    base = BaseInstruction(
        id="g1", requester="xu", text="Print my file.", parts=(Part(kind="print"),)
    )
    with pytest.raises(ValueError, match="nobody runs the printer"):
        check_base(base, office)


@pytest.mark.parametrize(
    ("facility", "guard", "text", "goal"),
    [
        ("printer", "xu", "Print my file and bring the printout to me.", "printout:xu"),
        ("coffee_machine", "gao", "Make me a coffee, please.", "coffee:gao"),
    ],
)
async def test_the_embedded_planner_lets_the_only_guard_run_it(
    facility: str, guard: str, text: str, goal: str
) -> None:
    office = _only_guard(facility, guard)
    sim = SimOffice(office)
    assistant = sim_assistant(sim, build_factory(office, Settings()))
    stm = await run_one(sim, assistant, guard, text)
    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"holds": [guard, goal]})
    kinds = [r.action.type for r in stm.trace.actions()]
    assert "inquire" not in kinds and "forward_file" not in kinds  # nobody else; their file
