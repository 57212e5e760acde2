"""An item kept at a facility is used when nobody's is named (issue 23, item 5): "get me a
label maker" in the harbour office fetches the one in the stationery cupboard, through its
keeper and with its owner's own yes, in the embedded planner and in the oracle alike."""

from __future__ import annotations

from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.office import Office, load_office
from assistantx.core.task_spec import BaseInstruction, Part


async def test_the_cupboards_label_maker_is_fetched_when_no_owner_is_named(
    harbour: Office,
) -> None:
    run = await run_instruction(harbour, "hope", "Could you get me a label maker?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["hope", "label_maker:may"]})
    # the owner was asked in her own chat before her label maker left the cupboard
    asked = [m for m in run.sim.messenger.sent if m.chat.id == "may"]
    assert asked and "label maker" in asked[0].text


def test_the_oracle_plans_the_same_source(harbour: Office) -> None:
    base = BaseInstruction(
        id="k1",
        requester="hope",
        text="Could you get me a label maker?",
        parts=(Part(kind="fetch", item="label_maker"),),
    )
    plan = build_plan(base, harbour)
    assert {"holds": ["hope", "label_maker:may"]} in plan.goal
    assert [r.key for r in plan.roles] == ["person:may", "guard:cupboard"]


def test_a_personal_item_is_never_taken_from_the_fridge_unnamed(harbour: Office) -> None:
    assert harbour.kept_owner("lunch") is None
    assert harbour.kept_owner("label_maker") == "may"
    assert harbour.kept_owner("label_maker", besides="may") is None


def test_place_names_name_locations_and_the_facilities_in_them(harbour: Office) -> None:
    names = harbour.place_names()
    assert names["supply room"] == "supply_room"
    assert names[harbour.facility("cupboard").name.lower()] == "supply_room"


async def test_a_consumable_is_asked_to_be_spared_not_lent() -> None:
    office = load_office()
    assert office.item_type("paper").consumable
    run = await run_instruction(office, "chen", "Please get me some paper.")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = run.sim.messenger.sent[0].text
    assert "spare Chen Jie some of your paper" in asked
    assert "lend" not in asked
