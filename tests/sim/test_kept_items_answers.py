"""An owner whose item the office keeps at a facility (a stapler in the stationery cupboard)
answers from the truth: asked to lend it, they say yes and that it is kept in the cupboard and
who takes it out, never "I have one"; in a group chat they do not volunteer to lend it from
their desk. The same rule as the oracle's, so the dataset generator's verification (which
plays the oracle against these simulated people) agrees with its dry run."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.oracle.plan import Role, able
from assistantx.agents.symbolic.answers import stance
from assistantx.core.office import Office, load_office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.evaluation.dataset.generate import verify_tasks
from assistantx.sim.people import direct_reply, group_replies
from assistantx.sim.world import World
from helpers.dataset_offices import harbour_office
from helpers.dataset_tasks import every_task


@functools.cache
def print_shop() -> Office:
    """Cy's stapler is kept in the cupboard Kit looks after; Cy runs the shredder in the same
    supply room (so the cupboard's room is one of Cy's places), Bea keeps hers at her desk."""
    desks = [("ann", "Ann Roe"), ("bea", "Bea Lund"), ("cy", "Cy Park"), ("kit", "Kit Moss")]
    return parse_office(
        {
            "name": "print shop",
            "locations": [
                *(
                    {"id": f"desk_{p}", "kind": "workstation", "name": f"{n}'s desk", "x": x}
                    | {"y": 2.0}
                    for x, (p, n) in zip((2.0, 6.0, 10.0, 14.0), desks, strict=True)
                ),
                {"id": "supply_room", "kind": "facility", "name": "Supply room", "x": 8, "y": 9},
            ],
            "item_types": [
                {"id": "stapler", "name": "stapler"},
                {"id": "paper", "name": "paper", "kind": "personal"},
            ],
            "operations": [
                {"id": "shred", "name": "shred", "verbs": ["shred"], "input": "paper"},
            ],
            "people": [
                {
                    "id": p,
                    "name": n,
                    "location": f"desk_{p}",
                    "handle": f"@{p}",
                    "owns": (
                        [{"type": "stapler", "at": "supply_room", "facility": "cupboard"}]
                        if p == "cy"
                        else [{"type": "stapler"}]
                        if p == "bea"
                        else []
                    ),
                }
                for p, n in desks
            ],
            "facilities": [
                {
                    "id": "cupboard",
                    "name": "stationery cupboard",
                    "location": "supply_room",
                    "guards": ["kit"],
                },
                {
                    "id": "shredder",
                    "name": "shredder",
                    "location": "supply_room",
                    "operations": ["shred"],
                    "guards": ["cy"],
                },
            ],
            "groups": [{"id": "all", "name": "Everyone", "members": [p for p, _ in desks]}],
            "robot": {"home": "supply_room"},
        },
        "print shop",
    )


def test_an_owner_asked_to_lend_a_kept_item_says_where_it_is_and_who_takes_it_out(
    harbour: Office,
) -> None:
    world = World.from_office(harbour)
    keepers = [harbour.person(g).name for g in harbour.facility("cupboard").guards]
    reply = direct_reply(world, "may", "Hi May, could you lend Hope Mensah your label maker?")
    assert reply is not None
    assert stance(reply.text) == "yes"  # the owner's own consent
    assert "stationery cupboard" in reply.text
    assert any(k in reply.text for k in keepers)
    assert "I have" not in reply.text


def test_an_owner_who_runs_the_facility_that_keeps_it_says_they_take_it_out() -> None:
    office = print_shop()
    raw_guards = office.facility("cupboard").guards
    assert "cy" not in raw_guards
    reply = direct_reply(World.from_office(office), "cy", "Hi Cy, could you lend Ann your stapler?")
    assert reply is not None and "stationery cupboard" in reply.text
    assert "Kit Moss" in reply.text and stance(reply.text) == "yes"


def test_in_a_group_an_owner_of_a_kept_item_does_not_volunteer_to_lend_it() -> None:
    office = print_shop()
    world = World.from_office(office)
    replies = group_replies(
        world, ["bea", "cy", "kit"], "Does anyone have a stapler Ann could borrow?"
    )
    assert [r.person for r in replies] == ["bea"]
    world.set_available("bea", False)
    assert group_replies(world, ["bea", "cy", "kit"], "Does anyone have a stapler?") == []


@pytest.mark.parametrize("which", ["default", "harbour", "print shop"])
def test_group_volunteers_are_exactly_those_the_oracle_counts_able(which: str) -> None:
    office = {
        "default": load_office,
        "harbour": harbour_office,
        "print shop": print_shop,
    }[which]()
    world = World.from_office(office)
    everyone = [p.id for p in office.people]
    for t in office.item_types:
        if t.kind != "belonging":
            continue
        role = Role(key=f"owner:{t.id}", kind="owner", question="", item_type=t.id)
        said = {r.person for r in group_replies(world, everyone, f"Does anyone have a {t.name}?")}
        oracle = {p for p in everyone if able(role, office, p)}
        assert said == oracle, (which, t.id)


async def test_the_generators_verification_agrees_when_every_stapler_at_hand_is_away() -> None:
    # Kit (the cupboard's keeper) and Bea away: the oracle's dry run finds nobody, and the
    # simulated Cy no longer offers a stapler that is locked in the cupboard
    office = print_shop()
    base = BaseInstruction(
        id="s1",
        requester="ann",
        text="Could you get me a stapler?",
        parts=(Part(kind="fetch", item="stapler"),),
    )
    tasks = every_task(office, base)
    assert tasks
    away = [t for t in tasks if set(t.unavailable) >= {"kit", "bea"}]
    assert away and not any(t.achievable for t in away)
    await verify_tasks(office, tasks)  # raises DatasetError on a disagreement


@functools.cache
def deed_office() -> Office:
    """Two seals: Cy's is kept in the safe Kit looks after (Cy guards it too), Bea keeps hers
    at her desk; Ann has a deed to be sealed."""
    desks = [("ann", "Ann Roe"), ("bea", "Bea Lund"), ("cy", "Cy Park"), ("kit", "Kit Moss")]
    own_seal = {
        "bea": [{"type": "seal"}],
        "cy": [{"type": "seal", "at": "vault", "facility": "safe"}],
    }
    return parse_office(
        {
            "name": "deed office",
            "locations": [
                *(
                    {"id": f"desk_{p}", "kind": "workstation", "name": f"{n}'s desk", "x": x}
                    | {"y": 2.0}
                    for x, (p, n) in zip((2.0, 6.0, 10.0, 14.0), desks, strict=True)
                ),
                {"id": "vault", "kind": "facility", "name": "Vault", "x": 8, "y": 9},
            ],
            "item_types": [
                {"id": "seal", "name": "seal", "seals": True},
                {"id": "document", "name": "deed", "kind": "personal", "signable": True},
            ],
            "people": [
                {
                    "id": p,
                    "name": n,
                    "location": f"desk_{p}",
                    "handle": f"@{p}",
                    "owns": [{"type": "document"}, *own_seal.get(p, [])],
                }
                for p, n in desks
            ],
            "facilities": [
                {"id": "safe", "name": "safe", "location": "vault", "guards": ["kit", "cy"]},
            ],
            "groups": [{"id": "all", "name": "Everyone", "members": [p for p, _ in desks]}],
            "robot": {"home": "vault"},
        },
        "deed office",
    )


def test_in_a_group_an_owner_whose_seal_is_kept_in_a_safe_does_not_offer_to_seal() -> None:
    office = deed_office()
    world = World.from_office(office)
    question = "Could anyone stamp Ann Roe's deed with the seal?"
    assert [r.person for r in group_replies(world, ["bea", "cy", "kit"], question)] == ["bea"]
    role = Role(key="owner:seal", kind="owner", question="", item_type="seal")
    assert {p for p in ("bea", "cy", "kit") if able(role, office, p)} == {"bea"}


async def test_the_generators_verification_agrees_when_the_seal_at_hand_is_away() -> None:
    # Bea away: the dry run finds no seal at hand, and the simulated Cy (whose seal is in the
    # safe) no longer answers the group's call to stamp the deed
    office = deed_office()
    base = BaseInstruction(
        id="s1",
        requester="ann",
        text="Could you get my deed stamped with the seal?",
        parts=(Part(kind="seal"),),
    )
    tasks = every_task(office, base)
    away = [t for t in tasks if "bea" in t.unavailable]
    assert away and not any(t.achievable for t in away)
    await verify_tasks(office, tasks)
