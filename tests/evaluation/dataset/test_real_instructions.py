"""The dataset accepts instructions real people give (issue 23, item 5), and the optimal
policy achieves every task generated from them: asking for a kind of item you own (yours is
broken), fetching your own item from where it is kept, a facility's guard asking for its
service (another guard runs it)."""

from __future__ import annotations

import pytest

from assistantx.core.errors import DatasetError
from assistantx.core.office import Office, load_office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.evaluation.dataset.generate import generate, verify_tasks
from assistantx.sim.world import World
from helpers.dataset_tasks import every_task

BASES = (
    # dang owns a cup: "mine is leaking" asks for someone else's
    BaseInstruction(
        id="r1",
        requester="dang",
        text="Mine is leaking. Could you bring me another cup?",
        parts=(Part(kind="fetch", item="cup"),),
    ),
    # lee's own lunch, kept in the fridge: its keeper takes it out
    BaseInstruction(
        id="r2",
        requester="lee",
        text="Could you fetch my lunch from the fridge?",
        parts=(Part(kind="fetch", item="lunch", owner="lee"),),
    ),
    # gao runs the coffee machine with sun
    BaseInstruction(
        id="r3",
        requester="gao",
        text="Could you get me a coffee? I'm stuck at my desk.",
        parts=(Part(kind="make", item="coffee"),),
    ),
)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@pytest.mark.parametrize("base", BASES, ids=lambda b: b.id)
def test_the_loader_accepts_it(office: Office, base: BaseInstruction) -> None:
    check_base(base, office)


def test_asking_for_a_kind_you_own_is_still_refused_when_nobody_else_has_one(
    office: Office,
) -> None:
    people = [
        p.model_copy(update={"owns": tuple(o for o in p.owns if o.type != "cup")})
        if p.id != "dang"
        else p
        for p in office.people
    ]
    only_dang = office.model_copy(update={"people": tuple(people)})
    with pytest.raises(ValueError, match="nobody but the requester"):
        check_base(BASES[0], only_dang)


def test_your_own_item_does_not_count_as_another(office: Office) -> None:
    world = World.from_office(office)
    assert not world.check({"holds": ["dang", "cup:*"]})  # dang holds only their own


async def test_the_optimal_policy_achieves_every_generated_task(office: Office) -> None:
    # every variant of each (all levels, achievable or not), labelled as the generator does
    tasks = every_task(office, *BASES)
    assert {t.base for t in tasks} == {"r1", "r2", "r3"}
    assert any(t.achievable for t in tasks if t.base == "r2")
    await verify_tasks(office, tasks)


def test_a_base_the_optimal_agent_cannot_do_with_everyone_in_is_named_in_one_line(
    office: Office,
) -> None:
    # Lee's own lunch asked for without `owner: lee`: the parts mean someone else's lunch,
    # lent, which nobody does; the generator said only StopIteration.
    base = BaseInstruction(
        id="own-lunch",
        requester="lee",
        text="grab my lunch out of the fridge pls",
        parts=(Part(kind="fetch", item="lunch"),),
    )
    with pytest.raises(DatasetError, match=r"'own-lunch' .* run is unachievable; check its parts"):
        generate(office, [base])
