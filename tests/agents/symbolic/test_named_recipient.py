"""Whom a thing is for when the request names someone else (blind round 57-58's class; the
round's own offices and sentences were never read): "could <person> have / get a <thing>",
"<person> could do with one" and "get <person> a <thing>" name the one who receives it, and an
alias made of a title and an initial ("Mr K", "Dr N") is a name like any other. "Could I get a
coffee" is the requester's; "could Mr K get me a coffee" makes Mr K the maker or the source,
and the requester receives."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


def _deliveries(text: str) -> list[tuple[str, str | None, str]]:
    return [(t.kind, t.item, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Could Mr K have a coffee? he's in with the auditors. Black, one sugar",
            [("produce", "coffee", "kofi")],
        ),
        ("could Kit get a tea", [("produce", "tea", "kit")]),
        ("can Dr N get a tea?", [("produce", "tea", "nadia")]),
        ("could Dr N have a pen please", [("transfer", "pen", "nadia")]),
        ("Could Mr K borrow a pen", [("transfer", "pen", "kofi")]),
        ("Mr K could do with a coffee", [("produce", "coffee", "kofi")]),
        # "Tam could do with a coffee" is Tam's need, restated and asked as "Tam needs a
        # coffee" is: test_named_want
        ("get Mr K a tea", [("produce", "tea", "kofi")]),
        ("bring Dr N a pen", [("transfer", "pen", "nadia")]),
    ],
)
def test_the_person_named_receives(text: str, expected: list[Any]) -> None:
    assert _deliveries(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "could I get a coffee",
        "could Mr K get me a coffee",
        "can Dr N get me a tea",
        "could I have a pen",
    ],
)
def test_the_requester_still_receives(text: str) -> None:
    assert [t.recipient for t in _frame(text).tasks] == ["ravi"], _frame(text)


async def test_end_to_end_the_coffee_goes_to_the_one_named() -> None:
    run = await run_instruction(staff_room(), "ravi", "Could Mr K have a coffee? Black, one sugar")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    to = [e.detail.get("to") for e in run.sim.world.handovers() if e.detail.get("to")]
    assert "kofi" in to and "ravi" not in to, run.stm.trace.summary
