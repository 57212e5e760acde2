"""A second clause with its own wish keeps its own recipient (blind round 57-58's class; the
round's own offices and sentences were never read): "send my tripod to Noor, and I'd like my
flask as well" hands the tripod to Noor and the flask to the requester, whose "I'd like / I
want / I need" it is. A coordinated object with no recipient of its own ("and my flask too")
still goes where the clause before sends things."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


@pytest.mark.parametrize(
    "text",
    [
        "Send my tripod to Noor, and I'd like my flask from the fridge as well",
        "send my tripod to Noor, then I need my flask",
        "send my tripod to Noor and i want my flask too",
        "give my tripod to Noor and I'd also like my flask",
        "take my tripod to Noor and bring me my flask",
        "Send my tripod to Noor. I'd like my flask too",
    ],
)
def test_the_wish_is_the_requesters(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [
        ("tripod", "noor"),
        ("flask", "ravi"),
    ], frame


@pytest.mark.parametrize(
    "text",
    ["send my tripod to Noor and my flask too", "send my tripod and my flask to Noor"],
)
def test_a_coordinated_object_goes_with_the_clause_before(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [
        ("tripod", "noor"),
        ("flask", "noor"),
    ], frame
