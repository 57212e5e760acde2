"""The speaker's account of their own doing with a need joined to it by "and" ("I'm covering a
class after lunch and need a stopwatch. thanks!!"): the need is a request of its own, the account
context, and a thanks after it politeness (blind round 57's class; its offices and sentences were
never read). An account with no need, or a need of nothing, is still only thanked for."""

from __future__ import annotations

import pytest

from helpers.bursary import bursary
from helpers.reading import frame_reader

_frame = frame_reader(bursary, "ana")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I'm covering Sam's class after lunch and need a stopwatch. thanks!!", "stopwatch"),
        ("I'm covering a class after lunch and I need a stopwatch", "stopwatch"),
        ("I'm running a race later and need a stopwatch. ta", "stopwatch"),
        ("we're doing a fire drill and could use a torch. cheers", "torch"),
        ("I am checking the hallmarks and would like a loupe, thanks!", "loupe"),
        ("I'll be marking all afternoon and want a stapler. cheers", "stapler"),
    ],
)
def test_a_need_joined_to_ones_own_doing_is_a_request(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "ana")], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    [
        "I'm covering a class, thanks!!",
        "I'm busy and need nothing, thanks",
        "I'm fine and need nothing. thanks!",
    ],
)
def test_an_account_without_a_need_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "welcome" in frame.decline, frame
