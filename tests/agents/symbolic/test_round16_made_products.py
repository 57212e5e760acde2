"""A product made from nothing by an operation whose id is an ordinary verb that does not
describe it ("bundle", named "make up a kit bag"), on a workshop no sentence was written for
(``helpers.fablab``; the blind round's office and sentences were never read): its keeper is
asked to make one, in the operation's own words, and agrees; never asked to find one ("get kit
bag from the stores cupboard"), which a keeper who has none refuses. A first aid kit (a "kit")
is still a thing to fetch."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.roles import Role, Roles
from assistantx.core.office import load_office
from helpers.dataset_offices import HARBOUR_FILE as HARBOUR
from helpers.fablab import fablab
from helpers.reading import frame_reader

_frame = frame_reader(fablab, "ines")


@pytest.mark.parametrize(
    ("who", "text"),
    [
        ("ines", "Could I get a kit bag made up for the Harlow workshop?"),
        ("ines", "could you make up a kit bag for me? rope and clips"),
        ("tomas", "can you make me up a kit bag"),
        ("hana", "I'd like a kit bag for tomorrow's site visit please"),
    ],
)
def test_a_made_product_is_asked_for(who: str, text: str) -> None:
    frame = _frame(text, who)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "kit_bag", who)]


def test_the_first_aid_kit_is_still_a_thing_to_fetch() -> None:
    frame = _frame("bring me Wanda's first aid kit", "ines")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [
        ("transfer", "first_aid_kit", "wanda")
    ]


def _produce_role(office_item: str, facility: str) -> Role:
    return Role(
        key="0.maker", kind="produce", requester="ines", item_type=office_item, facility=facility
    )


def test_the_keeper_is_asked_to_make_it_in_the_operations_words() -> None:
    roles = Roles(fablab(), lambda a, b: 0.0)
    asked = roles.question(_produce_role("kit_bag", "stores"), "wanda")
    assert asked == (
        "Hi Wanda, could you make up a kit bag for Ines Varga at the stores cupboard? "
        "The robot will come to you for the hand-over."
    )


def test_a_product_the_operations_name_does_not_say_is_named_itself() -> None:
    """The default office's "buy a snack" says its product: asked so; the harbour's "hand
    out supplies" does not say its notepad: the plain "get a notepad from ..." stays."""
    for path, op_id, product, name_said in (
        (None, "vend", "snack", True),
        (HARBOUR, "supply", "notepad", False),
    ):
        office = load_office(path)
        roles = Roles(office, lambda a, b: 0.0)
        where = office.offering(op_id)[0]
        requester = office.people[0]
        role = Role(
            key="0.m", kind="produce", requester=requester.id, item_type=product, facility=where.id
        )
        asked = roles.question(role, where.guards[0])
        made = f"{office.operation(op_id).name} for {requester.name} at the {where.name}"
        got = f"get {office.item_type(product).name} for {requester.name} from the {where.name}"
        assert (made in asked, got in asked) == (name_said, not name_said), asked


async def test_the_kit_bag_is_made_up_and_handed_over() -> None:
    run = await run_instruction(
        fablab(), "ines", "Could I get a kit bag made up for the Harlow workshop?"
    )
    assert run.stm.trace.outcome == "done"
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert "make up a kit bag" in asked[0].question  # type: ignore[union-attr]
    assert run.sim.world.holder["kit_bag:ines"] == "ines"
