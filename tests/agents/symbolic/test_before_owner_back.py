"""A colleague's thing asked for before its owner is back or sees ("grab Ana's stapler before
she's back", "take his seal and stamp my invoices before he gets back", "before anyone sees")
is taken behind their back: declined in words like "while he's not looking" (blind rounds
61-62's class: the owner was asked and, on their yes, the thing was used). A time limit
("before the meeting", "before 3pm", "before I get back") is read as before."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    "text",
    [
        "take Björn's seal and stamp all my invoices before he gets back",
        "grab Dara's stapler before she's back",
        "borrow Owen Marsh's stapler before he notices",
        "could you fetch Olive's seal before she gets in",
        "take his stapler before he returns",
        "grab Dara's stapler before Dara gets back",
        "nab Björn's stapler for me before anyone sees",
        "get me Dara's stapler, before she comes back",
    ],
)
def test_a_thing_taken_before_its_owner_is_back_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "without the owner knowing" in frame.decline


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Dara's stapler before the meeting", "dara"),
        ("can you get Björn's stapler to me before 3pm", "bjorn"),
        ("grab Dara's stapler for me before she leaves", "dara"),
        ("take my stapler to Dara before I get back", "jeanluc"),
    ],
)
def test_a_time_limit_is_read_as_before(text: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.owner) for t in frame.tasks] == [("transfer", owner)], frame


def test_nobodys_thing_before_someone_is_back_is_read_as_before() -> None:
    frame = _frame("bring me some batteries before my boss gets back")
    assert frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "batteries")], frame
