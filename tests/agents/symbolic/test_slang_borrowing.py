"""Slang for borrowing with a bare possessive: "left my ruler at home, can i nick zoe's for the
afternoon? she won't mind" borrows Zoë's ruler for the requester, Zoë asked first (blind round
40's class; the round's own sentences were never read). How long it is had ("for the
afternoon", "for an hour") is read away after the possessive, so the possessive stands for the
thing named before it; "yours" does so in a message addressed to a colleague. A plain request
and a purpose after the possessive keep their old reading."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from helpers.reading import frame_reader
from helpers.ward import ward

_frame = frame_reader(ward, "omar")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        (
            "left my ruler at home, can i nick zoe's for the afternoon? she won't mind",
            "ruler",
            "zoe",
        ),
        ("left my ruler at home, can i borrow Zoe's for an hour", "ruler", "zoe"),
        ("my stapler's jammed, could I pinch Pia's for a few minutes", "stapler", "pia"),
        ("forgot my ruler. Can I swipe Kofi's for the rest of the day?", "ruler", "kofi"),
        ("Zoe, left my ruler at home, mind if I swipe yours?", "ruler", "zoe"),
        ("hey Pia, my stapler's jammed, can I pinch yours for an hour", "stapler", "pia"),
        ("can i borrow zoe's ruler for an hour", "ruler", "zoe"),
        ("left my ruler at home, can i borrow zoe's?", "ruler", "zoe"),
    ],
)
def test_a_colleagues_thing_borrowed_in_slang(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "omar")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "can I pinch Zoe's for an hour",  # nothing named that it could be
        "left my ruler at home, mind if I swipe yours",  # said to nobody in particular
        "can I borrow zoe's for the exam",
    ],
)
def test_a_possessive_with_nothing_it_stands_for_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None and frame.question is not None, frame


def test_yours_said_of_a_subject_is_not_a_thing_asked_for() -> None:
    frame = _frame("Zoe, yours is broken, bring me a ruler")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "ruler", None)], frame


async def test_end_to_end_the_owner_is_asked_before_the_thing_moves() -> None:
    text = "left my ruler at home, can i nick zoe's for the afternoon? she won't mind"
    run = await run_instruction(ward(), "omar", text)
    trace = run.stm.trace
    actions = list(trace.actions())
    asked = [n for n, r in enumerate(actions) if getattr(r.action, "contact", None) == "zoe"]
    moved = [n for n, r in enumerate(actions) if isinstance(r.action, Move)]
    assert asked, trace.summary
    assert not moved or asked[0] < moved[0], trace.summary
