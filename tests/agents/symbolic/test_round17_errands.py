"""Blind round 17's errand classes, on a school arts block no sentence was written for
(``helpers.arts_block``; the round's office and sentences were never read).

4. An operation, then a second errand ("Get my tunic pressed and then bring me a coffee"):
   both, in order, and both happen.
5. "take X down to repro to be bound": "repro", the clipped name of the Reprographics room
   where the comb binder stands, and "to be bound" the binder's work, done there and the
   item back to the requester; "take my portfolio down to repro" with no work said is the
   room's one service on a portfolio, the binding (``reading.room_service``)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.clipped_names import clipped_names
from assistantx.core.office import parse_office
from helpers.arts_block import arts_block, raw_arts_block
from helpers.reading import frame_reader

_frame = frame_reader(arts_block, "hatty")


# -- 4. an operation then a second errand ---------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "Get my tunic pressed and then bring me a coffee please",
        "could you get my tunic pressed, then make me a coffee",
        "press my tunic and then get me a coffee",
    ],
)
def test_an_operation_then_an_errand_are_both_read_in_order(text: str) -> None:
    frame = _frame(text, "hatty")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.operation, t.recipient) for t in frame.tasks] == [
        ("heat", "tunic", "press", "hatty"),
        ("produce", "coffee", None, "hatty"),
    ]


async def test_the_tunic_is_pressed_and_the_coffee_brought() -> None:
    run = await run_instruction(
        arts_block(), "hatty", "Get my tunic pressed and then bring me a coffee please"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    world = run.sim.world
    assert world.check({"heated": ["tunic:hatty"]})
    assert world.holder["tunic:hatty"] == "hatty" and world.holder["coffee:hatty"] == "hatty"


# -- 5. "take X to P to be V-ed", P said clipped --------------------------------------------


@pytest.mark.parametrize(
    ("who", "text"),
    [
        ("priya", "Would you take my portfolio down to repro to be bound? Deadline is Friday."),
        ("bram", "could you take my portfolio down to repro to be bound please"),
        ("priya", "Would you take my portfolio to reprographics to be bound?"),
        ("priya", "take my portfolio to the comb binder to be bound"),
    ],
)
def test_taken_to_a_place_to_be_bound_is_the_binding(who: str, text: str) -> None:
    frame = _frame(text, who)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("bind", "portfolio", who, who)
    ]


def test_taken_to_repro_with_no_work_named_is_its_one_service_on_the_portfolio() -> None:
    # the comb binder is the room's one service on a portfolio (``reading.room_service``):
    # before, who in the room should get it was asked
    frame = _frame("take my portfolio down to repro please", "priya")
    assert frame.question is None, frame
    assert [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("bind", "portfolio", "priya", "priya")
    ]


def test_a_clipped_name_is_a_word_in_use_and_no_dictionary_word() -> None:
    assert clipped_names([("reprographics", "r")], set())["repro"] == "r"
    assert "photo" not in clipped_names([("photography", "p")], set())  # "photo": a word
    # a clip two names share names neither
    assert "repro" not in clipped_names([("reprographics", "r"), ("reproduction", "s")], set())
    assert "repro" not in clipped_names([("reprographics", "r")], {"repro"})


def test_a_room_named_with_room_after_it_is_clipped_from_its_first_word() -> None:
    # "Reprographics room" is said "repro" as "Reprographics" is; a longer name is not clipped
    assert clipped_names([("reprographics room", "r")], set())["repro"] == "r"
    assert clipped_names([("reprographics office", "r")], set())["repro"] == "r"
    assert "repro" not in clipped_names([("reprographics and print room", "r")], set())
    assert "repro" not in clipped_names([("reprographics kit", "r")], set())


def test_taken_to_a_clipped_room_to_be_bound_is_the_binding() -> None:
    raw = raw_arts_block()
    for place in raw["locations"]:
        if place["name"] == "Reprographics":
            place["name"] = "Reprographics room"
    frame = InstructionParser(parse_office(raw, "arts_block")).parse(
        "Would you take my portfolio down to repro to be bound? Deadline is Friday.", "priya"
    )
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.recipient) for t in frame.tasks] == [
        ("bind", "portfolio", "priya")
    ]


async def test_the_portfolio_is_bound_and_comes_back() -> None:
    run = await run_instruction(
        arts_block(),
        "priya",
        "Would you take my portfolio down to repro to be bound? Deadline is Friday.",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"heated": ["portfolio:priya"]})
    assert run.sim.world.holder["portfolio:priya"] == "priya"
    asked = [m.text for m in run.sim.messenger.sent if m.chat.id == "colm"]
    assert any("bind" in a for a in asked), asked


async def test_taken_to_repro_with_no_work_named_is_bound_and_comes_back() -> None:
    run = await run_instruction(arts_block(), "priya", "take my portfolio down to repro please")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"heated": ["portfolio:priya"]})
    assert run.sim.world.holder["portfolio:priya"] == "priya"
