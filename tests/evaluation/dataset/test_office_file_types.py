"""The dataset generator and the optimal policy on offices whose electronic file type is not
called ``file`` (issue 23: an outside writer's office, its file type ``script``, crashed
``dataset generate`` with ``unknown item type 'file'``), and the two-part errand whose file
goes to a keeper of the very machine that works on it.

Every variant the generator classifies is run through the simulated office by the optimal
policy (``verify_tasks``): the labels hold, every milestone is reached."""

from __future__ import annotations

import pytest

from assistantx.agents.oracle.plan import build_plan
from assistantx.agents.oracle.policy import dry_run
from assistantx.core.actions import ForwardFile, Inquire, SendQR
from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from helpers.dataset_tasks import verify_every_variant
from helpers.rehearsal_rooms import drafting_studio, rehearsal_rooms


async def _verify_every_variant(office: Office, base: BaseInstruction) -> None:
    check_base(base, office)
    await verify_every_variant(office, base)


def _bases(office: Office, requester: str, other: str, third: str) -> list[BaseInstruction]:
    """The file's errands, said in the office's words: worked on at the machine (for the
    requester, then for someone else), passed on, asked for from a colleague. (The consent
    guard reads the text for whom the requester named.)"""
    file = office.item_type(office.file_type() or "").name
    op = office.with_shape("render")[0]
    product = office.item_type(op.product or "").name
    name = {p: office.person(p).name for p in (other, third)}
    return [
        BaseInstruction(
            id="f1",
            requester=requester,
            text=f"Could you {op.name} my {file} into a {product} for me?",
            parts=(Part(kind="print"),),
        ),
        BaseInstruction(
            id="f2",
            requester=requester,
            text=f"Please {op.name} my {file} and take the {product} to {name[other]}.",
            parts=(Part(kind="print", to=other),),
        ),
        BaseInstruction(
            id="f3",
            requester=requester,
            text=f"Send my {file} to {name[third]}, please.",
            parts=(Part(kind="forward_file", to=third),),
        ),
        BaseInstruction(
            id="f4",
            requester=requester,
            text=f"Could you get me {name[other]}'s {file}?",
            parts=(Part(kind="get_file", owner=other),),
        ),
    ]


OFFICES = {
    "script": (rehearsal_rooms, ("priya", "bruno", "kwesi")),
    "drawing": (drafting_studio, ("femi", "greta", "yusuf")),
}
CASES = [
    pytest.param(name, base, id=f"{name}-{base.id}")
    for name, (make, people) in OFFICES.items()
    for base in _bases(make(), *people)
]


@pytest.mark.parametrize(("office_name", "base"), CASES)
async def test_every_variant_of_a_file_errand_is_solved(
    office_name: str, base: BaseInstruction
) -> None:
    await _verify_every_variant(OFFICES[office_name][0](), base)


@pytest.mark.parametrize("office_name", OFFICES)
def test_the_goal_names_the_offices_file(office_name: str) -> None:
    make, (requester, other, third) = OFFICES[office_name]
    office = make()
    file_type = office.file_type()
    goals = {b.id: build_plan(b, office).goal for b in _bases(office, requester, other, third)}
    assert {"printed": f"{file_type}:{requester}"} in goals["f1"]
    assert {"received": [third, f"{file_type}:{requester}"]} in goals["f3"]
    assert {"received": [requester, f"{file_type}:{other}"]} in goals["f4"]


@pytest.mark.parametrize("office_name", OFFICES)
def test_the_owner_is_asked_for_the_file_by_the_offices_name_for_it(office_name: str) -> None:
    make, people = OFFICES[office_name]
    office = make()
    base = _bases(office, *people)[3]
    [role] = build_plan(base, office).roles
    name = office.item_type(office.file_type() or "").name
    assert f"send me your {name} for" in role.question


# -- the two-part errand: a product for A, the file itself to B, a keeper of the machine ----

PACK_AND_SCRIPT = BaseInstruction(
    id="two",
    requester="ines",
    text="Please make up a script pack from my script for Bruno and send my script to Tomas.",
    parts=(Part(kind="print", to="bruno"), Part(kind="forward_file", to="tomas")),
)


def test_the_keeper_who_gets_the_file_is_sent_it_once() -> None:
    """Ines and Tomas keep the photocopier; Tomas makes the pack (Ines asked, so not her) and
    is the one the script is to go to: one forward serves both, a second would only repeat
    it (and the runtime refuses a repeat)."""
    office = rehearsal_rooms()
    run = dry_run(PACK_AND_SCRIPT, build_plan(PACK_AND_SCRIPT, office), office, set())
    forwards = [a for a in run.actions if isinstance(a, ForwardFile)]
    assert [(f.source, f.target) for f in forwards] == [("ines", "tomas")]
    assert [a.contact for a in run.actions if isinstance(a, Inquire)] == ["tomas", "bruno"]
    codes = [(a.contact, a.item, a.purpose) for a in run.actions if isinstance(a, SendQR)]
    assert codes == [
        ("tomas", "script_pack:ines", "produce"),
        ("bruno", "script_pack:ines", "collect"),
    ]
    assert run.outcome == "done"


def _to(to: str) -> BaseInstruction:
    """The errand with the script going to ``to`` instead of Tomas."""
    name = rehearsal_rooms().person(to).name
    return PACK_AND_SCRIPT.model_copy(
        update={
            "text": PACK_AND_SCRIPT.text.replace("Tomas", name),
            "parts": (Part(kind="print", to="bruno"), Part(kind="forward_file", to=to)),
        }
    )


def test_a_file_for_someone_besides_the_keeper_is_still_forwarded_twice() -> None:
    office = rehearsal_rooms()
    base = _to("kwesi")
    run = dry_run(base, build_plan(base, office), office, set())
    forwards = [(a.source, a.target) for a in run.actions if isinstance(a, ForwardFile)]
    assert forwards == [("ines", "tomas"), ("ines", "kwesi")]


@pytest.mark.parametrize("to", ["tomas", "kwesi"], ids=["to-the-keeper", "to-a-colleague"])
async def test_every_variant_of_the_two_part_errand_is_solved(to: str) -> None:
    await _verify_every_variant(rehearsal_rooms(), _to(to))


async def test_the_two_part_errand_with_a_third_keeper_is_solved() -> None:
    """With Hedda keeping the photocopier too, whoever makes the pack, the script still
    reaches Tomas, once."""
    office = rehearsal_rooms()
    facilities = tuple(
        f.model_copy(update={"guards": (*f.guards, "hedda")}) if f.id == "photocopier" else f
        for f in office.facilities
    )
    await _verify_every_variant(
        office.model_copy(update={"facilities": facilities}), PACK_AND_SCRIPT
    )
