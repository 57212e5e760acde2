"""A request to act behind an owner's back is declined in words (blind round 24's default
office: "borrow Zhang's stapler without telling him, he's in a mood today" took it, with
Zhang's yes, though the requester asked that he not know). The owner's yes is asked in their
own chat whatever the text says; "he won't mind" and "without asking me again" keep nobody
in the dark, and are read as before."""

from __future__ import annotations

import pytest

from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "borrow Rory's stapler without telling him, he's in a mood today",
        "grab me Miles's stapler, don't tell him",
        "can you get Thandi's stapler for me on the quiet",
        "take Rory's keyboard to Penny behind his back",
        "bring me Rory's stapler without him knowing",
    ],
)
def test_behind_the_owners_back_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "without the owner knowing" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "borrow Rory's stapler, he won't mind",
        "bring me Rory's stapler without asking me again",
        "bring me Rory's stapler",
    ],
)
def test_the_owner_is_asked_as_ever(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "rory", "ada")
    ], frame
