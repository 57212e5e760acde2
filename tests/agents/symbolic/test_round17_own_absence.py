"""A statement about the speaker's own absence (blind round 17's class, on a school office no
sentence was written for, ``helpers.playschool``): "just fyi I'm off site this afternoon with
the year 9 trip to the Science Museum", "I'm out at a meeting till 2 btw", "heads up I'm wfh
tomorrow" are told, not asked: answered in words, nothing moves (on main "just fyi" was no
opener, so the first was asked about). A request beside such a statement is still read."""

from __future__ import annotations

import pytest

from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "just fyi I'm off site this afternoon with the year 9 trip to the Science Museum",
        "I'm out at a meeting till 2 btw",
        "heads up I'm wfh tomorrow",
        "just a heads up, I'm out till 3 with year 11",
        "just btw I'm off site all day Friday",
        "just to let you know I'm off sick tomorrow",
        "to be clear, I'm away on the Berlin trip until Monday",
    ],
)
def test_the_speakers_own_absence_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline
    assert "bring it then" not in frame.decline  # told, not a need for later


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        (
            "just fyi I'm off site this afternoon, could you take my stapler to Rory",
            "stapler",
            "rory",
        ),
        ("just fyi Rory's stapler is broken, bring me Penny's", "stapler", "ada"),
        ("heads up I'm wfh tomorrow, so can you bring Miles my stapler now", "stapler", "miles"),
    ],
)
def test_a_request_beside_it_is_read(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)], frame
