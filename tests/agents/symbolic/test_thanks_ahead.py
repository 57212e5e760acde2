"""Gratitude in the conditional asks for what follows ("I'd be grateful for a box of staples
from the supply room when you get a sec" was answered "You're welcome!": blind round 28's
class); gratitude for what was done is thanks, answered in words, and moves nothing."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        (
            "I'd be grateful for a box of staples from the supply room when you get a sec",
            "staples",
            None,
        ),
        ("I'd appreciate a box of staples from the supply room", "staples", None),
        ("we'd be very grateful for a ruler", "ruler", None),
        ("I'd be grateful for a ruler from Bruno", "ruler", "bruno"),
        ("I'd be grateful if you could bring me a box of staples", "staples", None),
    ],
)
def test_thanks_ahead_asks_for_the_thing(text: str, item: str, owner: str | None) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "ines")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "grateful for your help yesterday",
        "I'm grateful for the staples",
        "I'd appreciate it",
        "I'd be grateful for the staples you brought yesterday",
        "thanks, I'd really appreciate it",
        "I'd be so grateful, thanks",
    ],
)
def test_thanks_for_what_was_done_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "welcome" in frame.decline
