"""A plural of people in lower case with its apostrophe after the s, after a determiner ("the
trustees' file", "the governors' doc"), names a kind of paper, nobody to look up (blind round
57's class; its offices and sentences were never read): the paper is the requester's. A name
with its apostrophe after the s ("James' stapler") is still the person."""

from __future__ import annotations

import pytest

from helpers.bursary import bursary
from helpers.reading import frame_reader

_frame = frame_reader(bursary, "ana")


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("forward the trustees' file to Miles", "send_file", "miles"),
        ("send Gwen the parents' doc", "send_file", "gwen"),
        ("could you send the governors' file to Bronwen please", "send_file", "bronwen"),
        ("print the governors' file and take it to the Bursar", "print", "bursar"),
        ("please print the students' doc for Miles", "print", "miles"),
        # an everyday noun for the paper ("report", "minutes") reads the same way
        ("Please print the trustees' report and take it to the Bursar", "print", "bursar"),
        ("email the governors' minutes to Miles", "send_file", "miles"),
        ("send the governors' report to Bronwen", "send_file", "bronwen"),
    ],
)
def test_a_plural_of_people_before_a_paper_is_no_person(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, "file", "ana", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me James' stapler", "james"),
        ("forward James' file to Miles", "james"),
        ("could you get me Miles' torch", "miles"),
    ],
)
def test_a_name_with_its_apostrophe_after_the_s_is_still_the_person(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [t.owner for t in frame.tasks] == [owner], frame


def test_an_unknown_capitalised_name_is_still_asked_about() -> None:
    frame = _frame("forward Rhodes' file to Miles")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Rhodes" in frame.question, frame
