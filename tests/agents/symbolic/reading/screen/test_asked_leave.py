"""Slang for taking in a request for leave asks to borrow; told to the robot it is kept."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.asked_leave import asked_leave


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("can i nick Robin's mute for the Ravel?", "can i borrow Robin's mute for the Ravel?"),
        ("Could I just pinch a pen off you", "Could I just borrow a pen off you"),
        ("mind if we half inch your stapler", "mind if we borrow your stapler"),
    ],
)
def test_leave_asked_for_oneself_is_a_borrowing(text: str, read: str) -> None:
    out, evidence = asked_leave(text)
    assert out == read
    assert [e.meaning for e in evidence] == ["asks to borrow"]


@pytest.mark.parametrize(
    "text",
    ["nick Robin's mute for me", "can you pinch Min's mug", "someone nicked my pen"],
)
def test_a_taking_told_or_told_of_is_left_as_said(text: str) -> None:
    assert asked_leave(text) == (text, [])
