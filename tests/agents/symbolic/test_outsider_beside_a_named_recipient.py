""" "print my quote for the juke customer and give it to robin" (blind round 24's class): a
"for <someone outside>" beside a colleague named to receive the thing says what it is for;
the colleague gets it. On main the assistant asked whether to bring it to the requester
instead. With no colleague named, the outsider is still asked about."""

from __future__ import annotations

import pytest

from helpers.orchestra_pit import orchestra_pit
from helpers.reading import frame_reader

_frame = frame_reader(orchestra_pit, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "print my part for the customer and give it to Teodor pls, he's marking it up",
        "can you run off my part for the visitor and hand it to Teodor",
    ],
)
def test_the_colleague_named_receives(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "part", "teodor")]


def test_with_no_colleague_named_the_outsider_is_asked_about() -> None:
    frame = _frame("give my part to the visitor")
    assert frame.tasks == [] and frame.question is not None
    assert "I hand things only to people of this office" in frame.question


def test_my_own_part_printed_for_an_outsider_comes_to_me() -> None:
    # fixer 93d, class 3 (screen.own_serviced): the printout comes back to the requester
    frame = _frame("print my part for the customer")
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "part", "ines")]
