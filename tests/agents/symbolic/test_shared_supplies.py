"""Items owned by nobody (issue 23, items 1 and 5): supplies kept at a place for anyone (tape
and pens in a stationery cupboard) are fetched by the place's keeper with no one's yes, in
the embedded planner, the oracle and the dataset check alike; a count, when the office gives
one, can run out."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.agents.oracle.plan import build_plan
from assistantx.cli.office_cmd import describe
from assistantx.core.errors import OfficeError
from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.evaluation.dataset.generate import _task, classify, generate, verify_tasks
from assistantx.runtime.consent import consent_owner
from assistantx.sim.people import handover_problem
from assistantx.sim.world import World
from helpers.yaml_files import raw_yaml


def _raw(**cupboard: Any) -> dict[str, Any]:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    raw["item_types"].append(
        {"id": "tape", "name": "tape", "synonyms": ["sticky tape"], "consumable": True}
    )
    raw["facilities"].append(
        {
            "id": "cupboard",
            "name": "stationery cupboard",
            "location": "print_room",
            "guards": ["xu"],
            "supplies": [{"type": "tape"}, {"type": "pen"}],
            **cupboard,
        }
    )
    return raw


@pytest.fixture(scope="module")
def office() -> Office:
    return parse_office(_raw())


def test_a_supply_is_owned_by_nobody_and_kept_by_its_facility(office: Office) -> None:
    assert office.is_supply("tape:cupboard") and not office.is_supply("pen:lee")
    assert office.kept_owner("tape") == "cupboard"
    assert office.kept_owner("pen", besides="lee") == "cupboard"  # before a colleague's
    assert office.keeper("cupboard", "tape") == office.facility("cupboard")
    # nobody's yes is needed for it, whoever takes it out
    assert consent_owner(office, "lee", "tape:cupboard", "deposit", "xu") is None


async def test_tape_is_fetched_from_the_cupboard_without_asking_anyone_for_consent(
    office: Office,
) -> None:
    run = await run_instruction(office, "lee", "Could you get me some tape?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["lee", "tape:cupboard"]})
    chats = {m.chat.id for m in run.sim.messenger.sent}
    assert chats <= {"lee", "xu"}, chats  # only the requester and the cupboard's keeper
    assert not [r for r in run.stm.trace.actions() if r.refused]


def test_the_oracle_plans_the_keeper_alone(office: Office) -> None:
    base = BaseInstruction(
        id="s1",
        requester="lee",
        text="Could you get me some tape?",
        parts=(Part(kind="fetch", item="tape"),),
    )
    check_base(base, office)  # the dataset accepts it: nobody owns tape, the cupboard has it
    plan = build_plan(base, office)
    assert {"holds": ["lee", "tape:cupboard"]} in plan.goal
    assert [r.key for r in plan.roles] == ["guard:cupboard"]
    assert "the tape" in plan.roles[0].question


def test_a_supply_without_a_count_does_not_run_out(office: Office) -> None:
    world = World.from_office(office)
    assert world.holder["tape:cupboard"] == "print_room"
    world.move_item(0.0, "tape:cupboard", "locker", by="xu")
    assert world.in_stock("tape:cupboard")


def test_a_counted_supply_runs_out() -> None:
    office = parse_office(_raw(supplies=[{"type": "tape", "count": 0}]))
    world = World.from_office(office)
    assert not world.in_stock("tape:cupboard")
    problem = handover_problem(world, "xu", "deposit", "tape:cupboard", "print_room")
    assert problem == "There is no tape left here."
    counted = World.from_office(parse_office(_raw(supplies=[{"type": "tape", "count": 1}])))
    counted.move_item(0.0, "tape:cupboard", "locker", by="xu")
    assert not counted.in_stock("tape:cupboard")


@pytest.mark.parametrize(
    ("change", "problem"),
    [
        ({"supplies": [{"type": "glue"}]}, "unknown item type 'glue'"),
        ({"supplies": [{"type": "coffee"}]}, "not a product"),
        ({"guards": []}, "nobody guards it"),
    ],
)
def test_a_bad_supply_is_a_clear_office_error(change: dict[str, Any], problem: str) -> None:
    with pytest.raises(OfficeError, match=problem):
        parse_office(_raw(**change))


async def test_the_generator_verifies_tasks_on_an_office_with_shared_supplies(
    office: Office,
) -> None:
    """``dataset generate``'s check (the oracle solves each task in the sim, in the number of
    actions the dry run planned) accepts an office whose supplies nobody owns: "get me some
    tape" with everyone there, and with the cupboard's keeper away (nobody else can)."""
    base = BaseInstruction(
        id="s2",
        requester="lee",
        text="Could you get me some tape?",
        parts=(Part(kind="fetch", item="tape"),),
    )
    pools = classify(base, office)
    assert set(pools) == {"L1", "unachievable"}
    tasks = [_task(v, office, n) for n, v in enumerate((*pools["L1"], *pools["unachievable"]))]
    assert {"holds": ["lee", "tape:cupboard"]} in tasks[0].goal
    await verify_tasks(office, tasks)  # raises DatasetError naming the task otherwise


async def test_a_pen_comes_from_the_cupboard_first(office: Office) -> None:
    run = await run_instruction(office, "zhang", "Could you get me a pen?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["zhang", "pen:cupboard"]})


async def test_with_the_keeper_away_a_colleague_lends_one_with_their_own_yes(
    office: Office,
) -> None:
    """Issue 23 (kept-item fallback): the cupboard's keeper is away, so a colleague who has
    a pen at hand lends theirs, asked in their own chat; not "nobody could help"."""
    run = await run_instruction(office, "zhang", "Could you get me a pen?", unavailable=("xu",))
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["zhang", "pen:*"]})
    lender = next(i for i, h in run.sim.world.holder.items() if h == "zhang" and "pen:" in i)
    owner = lender.partition(":")[2]
    assert run.sim.world.office.is_person(owner)
    assert any(m.chat.id == owner and "pen" in m.text for m in run.sim.messenger.sent)


async def test_the_oracle_falls_back_alike(office: Office) -> None:
    base = BaseInstruction(
        id="s3",
        requester="zhang",
        text="Could you get me a pen?",
        parts=(Part(kind="fetch", item="pen"),),
    )
    pools = classify(base, office)
    assert "L2" in pools
    fell_back = [v for v in pools["L2"] if v.unavailable == frozenset({"xu"})]
    assert fell_back, pools
    task = _task(fell_back[0], office, 1)
    assert {"holds": ["zhang", "pen:*"]} in task.goal
    await verify_tasks(office, [task])  # the oracle in the sim: done, in the planned steps


def test_what_was_asked_admits_a_colleagues_pen_when_the_tape_makes_it_unachievable(
    office: Office,
) -> None:
    """Round 221 (blind): "bring me a drill and some gaffer tape" with the tool store's
    keepers away is unachievable (nobody lends tape), yet the drill part may be done with a
    colleague's drill, lent with their own yes, as the planner does; the task's requested
    goal said only the store's drill, so that hand-over counted as wrong."""
    base = BaseInstruction(
        id="s6",
        requester="zhang",
        text="Could you get me a pen and some tape?",
        parts=(Part(kind="fetch", item="pen"), Part(kind="fetch", item="tape")),
    )
    away = [v for v in classify(base, office)["unachievable"] if "xu" in v.unavailable]
    assert away
    task = _task(away[0], office, 1)
    assert task.goal == [{"informed": "zhang"}]
    assert {"holds": ["zhang", "pen:cupboard"]} in task.requested_goal
    assert {"holds": ["zhang", "pen:*"]} in task.requested_goal  # a colleague's, lent
    assert {"holds": ["zhang", "tape:cupboard"]} in task.requested_goal
    # an unachievable task that uses nothing kept asks only what it asked
    own = BaseInstruction(
        id="s7",
        requester="zhang",
        text="bring me Lee's book",
        parts=(Part(kind="fetch", item="book", owner="lee"),),
    )
    lee_away = [v for v in classify(own, office)["unachievable"] if "lee" in v.unavailable]
    assert _task(lee_away[0], office, 2).requested_goal == [
        {"holds": ["zhang", "book:lee"]},
        {"informed": "zhang"},
    ]


async def test_an_empty_counted_supply_sends_the_robot_to_a_colleague() -> None:
    office = parse_office(_raw(supplies=[{"type": "pen", "count": 0}]))
    run = await run_instruction(office, "zhang", "Could you get me a pen?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert not run.sim.world.check({"holds": ["zhang", "pen:cupboard"]})
    assert run.sim.world.check({"holds": ["zhang", "pen:*"]})


def test_the_oracle_skips_a_supply_the_office_says_is_empty() -> None:
    office = parse_office(_raw(supplies=[{"type": "pen", "count": 0}]))
    base = BaseInstruction(
        id="s4", requester="zhang", text="get me a pen", parts=(Part(kind="fetch", item="pen"),)
    )
    assert [r.key for r in build_plan(base, office).roles] == ["owner:pen"]


def test_a_small_office_gets_the_variants_it_has_not_a_refusal(
    office: Office, caplog: pytest.LogCaptureFixture
) -> None:
    """Round 4 (b4): one base cannot give the 22 distinct unachievable variants the default
    dataset aims for; ``dataset generate`` (verified by the oracle) takes what there is."""
    base = BaseInstruction(
        id="s5",
        requester="lee",
        text="Could you get me some tape?",
        parts=(Part(kind="fetch", item="tape"),),
    )
    tasks = generate(office, [base], verify=True)
    assert {t.level for t in tasks} == {"L1", "L3"} and not all(t.achievable for t in tasks)
    assert "distinct unachievable variants" in caplog.text


def test_office_show_lists_the_supplies() -> None:
    shown = describe(parse_office(_raw(supplies=[{"type": "tape"}, {"type": "pen", "count": 3}])))
    assert "stationery cupboard @ print_room: tape, pen (3)" in shown
