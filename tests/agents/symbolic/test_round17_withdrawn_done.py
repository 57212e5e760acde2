"""A withdrawal with its reason told as done by now (blind round 17's class, on a school office
no sentence was written for, ``helpers.playschool``): "bring me a script pack please. actually
never mind, Thandi's already run one off" drops the request in words and moves nothing (on
main the reason's "run one off" went unread and the whole message was asked about). A request
after the withdrawal is still read."""

from __future__ import annotations

import pytest

from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "bring me a script pack please. actually never mind, Thandi's already run one off",
        "bring me a script pack please. never mind, Thandi's already run one off, thanks",
        "could you get me Rory's stapler? oh never mind, Penny has just lent me hers",
        "can someone mix up some fake blood. never mind, Jun's already made some",
        "bring me a script pack please. actually never mind, I've already got one",
    ],
)
def test_a_withdrawal_with_its_reason_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me Rory's stapler. never mind, just bring me a script pack", "script"),
        ("never mind the stapler, Thandi's already run one off, bring me a script pack", "script"),
    ],
)
def test_a_request_after_the_withdrawal_is_read(text: str, item: str) -> None:
    frame = _frame(text)
    assert [t.item for t in frame.tasks] == [item], frame
