"""A request reported on a colleague's behalf (blind round 57-58's class; the round's own
offices and sentences were never read): "Professor Zhang asked if someone could bring him a
coffee, can you do that?" is a coffee for Zhang; "him"/"her" in the reported request is the
one reported, and a title before the name ("Professor", "Prof") is part of it. A report with
no ask, or one the speaker says they will do, moves nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        (
            "Professor Zhang asked if someone could bring him a coffee, can you do that?",
            "coffee",
            "zhang",
        ),
        ("Prof Zhang asked if someone could bring him a coffee", "coffee", "zhang"),
        ("Ana was wondering if anyone could take her the stapler", "stapler", "ana"),
        ("so Ana was wondering if anyone could take her the stapler", "stapler", "ana"),
        ("Ana was wondering if someone could bring her a pen, could you?", "pen", "ana"),
        ("Zhang asked if someone could bring him a tea", "tea", "zhang"),
        ("Mr K was asking whether anybody could bring him a tea", "tea", "kofi"),
        # said to the assistant already: read as before
        ("Zhang asked if you could bring him a tea", "tea", "zhang"),
    ],
)
def test_the_one_reported_receives(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)], frame


@pytest.mark.parametrize(
    "text",
    [
        "Zhang asked about the rota",
        "Zhang asked if I could bring him a tea",
    ],
)
def test_no_ask_of_ours_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_end_to_end_the_coffee_goes_to_the_one_reported() -> None:
    text = "Professor Zhang asked if someone could bring him a coffee, can you do that?"
    run = await run_instruction(staff_room(), "ravi", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    to = [e.detail.get("to") for e in run.sim.world.handovers() if e.detail.get("to")]
    assert "zhang" in to and "ravi" not in to, run.stm.trace.summary
