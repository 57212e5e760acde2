""" "Take my stapler to Rory for me" asks a favour: the "for me" that ends the clause after a
colleague named after "to" names no second recipient, so the stapler goes to Rory (the reader
asked "Who should get your stapler?"). Where "for me" says whom another thing is for ("a
stapler for Rory and a keyboard for me"), or more follows it, it is read as before."""

from __future__ import annotations

import pytest

from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "take my stapler to Rory for me",
        "run my stapler down to Rory for me please",
        "can you bring my stapler over to Rory for me, thanks",
    ],
)
def test_the_colleague_gets_it_as_a_favour_to_the_requester(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "rory")]


def test_for_me_with_a_thing_of_its_own_is_still_mine() -> None:
    frame = _frame("take my stapler to Rory and bring Penny's keyboard for me")
    assert ("transfer", "keyboard", "ada") in [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert ("transfer", "stapler", "rory") in [(t.kind, t.item, t.recipient) for t in frame.tasks]
