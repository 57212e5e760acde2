"""Dataset labels on an office unlike the default (issue 23, an outside evaluation): a made
thing with a named recipient is that person's to hold; person ids that share a first name
resolve as ids; an item kept in a cupboard, asked for without an owner, is achieved by the
optimal policy the generator verifies with."""

from __future__ import annotations

import pytest

from assistantx.agents.oracle.plan import build_plan
from assistantx.core.office import Office, Ownership
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.memory.resolve import Resolver
from helpers.dataset_tasks import verify_every_variant


@pytest.fixture(scope="module")
def two_robins(harbour: Office) -> Office:
    """The harbour office with two colleagues both called Robin, ids ``robin_a``/``robin_m``."""
    may = harbour.person("may")
    mark = harbour.person("mark")
    robins = (
        may.model_copy(
            update={"id": "robin_a", "name": "Robin Adler", "aliases": ("Robin",), "handle": "@ra"}
        ),
        mark.model_copy(
            update={"id": "robin_m", "name": "Robin Moss", "aliases": ("Robin",), "handle": "@rm"}
        ),
    )
    return harbour.model_copy(update={"people": (*harbour.people, *robins)})


MADE_FOR_SOMEONE = (
    BaseInstruction(
        id="m1",
        requester="may",
        text="Could you make Mark a cup of tea?",
        parts=(Part(kind="tea", to="mark"),),
    ),
    BaseInstruction(
        id="m2",
        requester="may",
        text="Could you scan my contract and take the scan to Mark?",
        parts=(Part(kind="copy", to="mark"),),
    ),
)


@pytest.mark.parametrize("base", MADE_FOR_SOMEONE, ids=lambda b: b.id)
def test_a_made_thing_with_a_recipient_is_the_recipients_to_hold(
    harbour: Office, base: BaseInstruction
) -> None:
    check_base(base, harbour)
    goal = build_plan(base, harbour).goal
    held = [m["holds"] for m in goal if "holds" in m]
    made = [h for h in held if h[1].split(":")[0] in ("tea", "scan")]
    assert [h[0] for h in made] == ["mark"], goal
    # a tea is made for Mark (the embedded planner names it so); a scan stays May's
    assert made[0][1] in ("tea:mark", "scan:may")
    assert all(t.recipient == "mark" for t in base.tasks(harbour))


@pytest.mark.parametrize("base", MADE_FOR_SOMEONE, ids=lambda b: b.id)
async def test_the_optimal_policy_brings_it_to_the_recipient(
    harbour: Office, base: BaseInstruction
) -> None:
    await verify_every_variant(harbour, base)


def test_an_id_resolves_as_that_id_before_any_name(two_robins: Office) -> None:
    resolver = Resolver(two_robins)
    assert resolver.person("robin_a") == "robin_a"
    assert resolver.person("robin_m") == "robin_m"
    assert resolver.item("ruler:robin_m") == "ruler:robin_m"


async def test_people_sharing_a_first_name_request_and_own_by_id(two_robins: Office) -> None:
    base = BaseInstruction(
        id="p1",
        requester="robin_a",
        text="Could you borrow Robin Moss's ruler for me?",
        parts=(Part(kind="fetch", item="ruler", owner="robin_m"),),
    )
    check_base(base, two_robins)
    await verify_every_variant(two_robins, base)


async def test_a_cupboard_item_asked_for_without_an_owner_is_achieved(harbour: Office) -> None:
    base = BaseInstruction(
        id="k1",
        requester="hope",
        text="Could you get me a label maker?",
        parts=(Part(kind="fetch", item="label_maker"),),
    )
    check_base(base, harbour)
    await verify_every_variant(harbour, base)


async def test_a_cupboard_item_with_another_at_a_desk_is_labelled_as_the_policy_plays(
    harbour: Office,
) -> None:
    # Mark keeps a label maker at his desk too: with both cupboard guards away, his offer of
    # his own in the group is no yes to "could anyone take it out of the cupboard?"
    people = tuple(
        p.model_copy(update={"owns": (*p.owns, Ownership(type="label_maker"))})
        if p.id == "mark"
        else p
        for p in harbour.people
    )
    office = harbour.model_copy(update={"people": people})
    base = BaseInstruction(
        id="k2",
        requester="hope",
        text="Could you get me a label maker?",
        parts=(Part(kind="fetch", item="label_maker"),),
    )
    check_base(base, office)
    await verify_every_variant(office, base)
