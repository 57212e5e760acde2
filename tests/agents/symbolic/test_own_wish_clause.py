"""A second clause with its own wish keeps its own recipient (blind round 57-58's class; the
round's own offices and sentences were never read): "send my tripod to Noor, and I'd like my
flask as well" hands the tripod to Noor and the flask to the requester, whose "I'd like / I
want / I need" it is. A coordinated object with no recipient of its own ("and my flask too")
still goes where the clause before sends things."""

from __future__ import annotations

import pytest

from helpers.lending_bench import lending_bench
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


# Blind round 59-60 class 1: a later clause whose subject is the requester with a verb of
# having ("could I borrow", "can I have", "may I take", "I'd like to borrow") asks for the
# thing for the requester, whoever an earlier clause sent things to; the owner is asked.
_bench = frame_reader(lending_bench, "mira")


@pytest.mark.parametrize(
    "text",
    [
        "Take my lamp to Bea, and could I borrow Jory's clamp in return?",
        "take my lamp over to Bea and can I have Jory's clamp please",
        "bring my lamp to Bea, and may I take Jory's clamp",
        "Take my lamp to Bea. Could I borrow Jory's clamp in return?",
        "give my lamp to Bea and I'd like to borrow Jory's clamp",
        "drop my lamp at Bea's desk and could I get Jory's clamp",
        "take my lamp to Bea, and may I use Jory's clamp for an hour",
        "take my lamp to Bea and I'll borrow Jory's clamp",
        "pass my lamp to Bea, and then can I grab Jory's clamp?",
    ],
)
def test_a_clause_of_having_is_the_requesters(text: str) -> None:
    frame = _bench(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("lamp", "mira", "bea"),
        ("clamp", "jory", "mira"),
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "take my lamp to Bea and my headphones too",
        "take my lamp and my headphones to Bea",
        "take my lamp to Bea and also my headphones",
    ],
)
def test_a_coordinated_object_still_goes_to_the_one_named(text: str) -> None:
    frame = _bench(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [
        ("lamp", "bea"),
        ("headphones", "bea"),
    ], frame
