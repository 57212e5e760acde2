"""Whose one is fine (blind round 57-58's class; the round's own offices and sentences were
never read): after a need, "<colleague>'s is fine / would do / will do / works" picks that
colleague's one, asked of them. "Lee's is broken", "not Lee's", "it's fine" pick nobody's."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "kit")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("i need a pen. lee's is fine", "pen", "lee"),
        ("need a charger, Ruth's would do", "charger", "ruth"),
        ("can you bring me a pen? Lee's will do", "pen", "lee"),
        ("i need a pen, Ruth's works", "pen", "ruth"),
        ("i need a pen - Ruth's is ok", "pen", "ruth"),
        ("Could you get me a charger? bron's would be fine", "charger", "bronwen"),
        ("i need a drill. Miles's works", "drill", "miles"),
    ],
)
def test_the_one_said_to_be_fine_is_wanted(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "kit")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "i need a pen. lee's is broken",
        "i need a pen, not Lee's",
        "i need a pen, it's fine",
        "i need a pen. that's fine",
        "i need a pen, Lee is fine with it",
    ],
)
def test_nobodys_in_particular_otherwise(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [("pen", None)], frame


async def test_end_to_end_the_owner_said_is_asked() -> None:
    run = await run_instruction(staff_room(), "kit", "i need a pen. lee's is fine")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("pen:lee", "kit") in handed, run.stm.trace.summary
