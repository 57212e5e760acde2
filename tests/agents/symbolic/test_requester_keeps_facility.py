"""The requester keeps the facility where a colleague's thing is kept: Hazel, the only keeper of
a dry cabinet that holds Tomás's filter set, asks "Fetch Tomás's filter set from the dry
cabinet, please." Tomás is asked for his yes; then the one who takes it out is Hazel herself
(her request is her yes), as the oracle plans it: the robot goes to the cabinet, sends her the
deposit and the collect codes and waits there. Before, "find who can take the filter set out
for the robot" skipped the requester, asked the whole staff group, and failed. Where a fellow
keeper exists, they are asked first; the requester takes it out before any group is asked."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.oracle.policy import dry_run
from assistantx.core.actions import Inquire, Move, SendQR
from assistantx.core.office import Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part
from helpers import office_builder as ob

TEXT = "Fetch Tomás's filter set from the dry cabinet, please."
BASE = BaseInstruction(
    id="keeps1",
    requester="hazel",
    text=TEXT,
    parts=(Part(kind="fetch", item="filter_set", owner="tomas"),),
)


def _studio(guards: tuple[str, ...]) -> Office:
    raw: dict[str, Any] = ob.office_file(
        "studio",
        (
            ob.person(
                "tomas",
                "Tomás Vidal",
                ob.kept("filter_set", at="darkroom", facility="dry_cabinet"),
            ),
            ob.person("hazel", "Hazel Grant"),
            ob.person("ivo", "Ivo Lind"),
        ),
        rooms=[ob.room("darkroom", "Darkroom", 4.0, 20.0), ob.room("store", "Store", 14.0, 20.0)],
        item_types=[ob.item("filter_set", "filter set", synonyms=["filters"])],
        operations=[],
        facilities=[ob.facility("dry_cabinet", "dry cabinet", at="darkroom", guards=guards)],
        home="store",
    )
    return parse_office(raw, "studio")


def _codes(run: Any) -> list[tuple[str, str]]:
    return [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if isinstance(r.action, SendQR)
    ]


def _asked(run: Any) -> list[str]:
    return [r.action.contact for r in run.stm.trace.actions() if isinstance(r.action, Inquire)]


async def test_the_only_keeper_asking_takes_it_out_herself_as_the_oracle_does() -> None:
    office = _studio(("hazel",))
    run = await run_instruction(office, "hazel", TEXT)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    plan = build_plan(BASE, office)
    assert [m for m in plan.goal if not run.sim.world.check(m)] == []
    assert _asked(run) == ["tomas"]  # the owner's yes; no group asked
    assert _codes(run) == [("hazel", "deposit"), ("hazel", "collect")]
    moves = [r.action.place for r in run.stm.trace.actions() if isinstance(r.action, Move)]
    assert moves == ["darkroom"]  # both codes at the cabinet, one stop
    oracle = dry_run(BASE, plan, office, set())
    assert oracle.outcome == "done"
    assert [(a.contact, a.purpose) for a in oracle.actions if isinstance(a, SendQR)] == _codes(run)


async def test_a_fellow_keeper_away_is_not_replaced_by_the_requester() -> None:
    # as the oracle plans it (``runs_it_alone`` only for the one keeper): with a fellow
    # keeper, the requester is not the one who takes it out, so with that keeper away and
    # nobody in the group, the errand cannot be done and says so
    office = _studio(("ivo", "hazel"))
    run = await run_instruction(office, "hazel", TEXT, unavailable=("ivo",))
    assert run.stm.trace.outcome == "unachievable", run.stm.trace.summary
    assert ("hazel", "deposit") not in _codes(run)


@pytest.mark.parametrize(
    ("guards", "requester", "keeper"),
    [
        # must not change: a fellow keeper there takes it out, as before
        (("ivo", "hazel"), "hazel", "ivo"),
        # must not change: a requester who keeps nothing asks the keeper
        (("hazel",), "ivo", "hazel"),
    ],
)
async def test_must_not_change_another_keeper_takes_it_out(
    guards: tuple[str, ...], requester: str, keeper: str
) -> None:
    office = _studio(guards)
    run = await run_instruction(office, requester, TEXT)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert (keeper, "deposit") in _codes(run)
    assert (requester, "collect") in _codes(run)
    assert keeper in _asked(run)
