"""A file named by the speaker's own doing ("print the meeting note I just saved and bring it
to me") is the requester's own, as "my meeting note" is: it asked which file "it" meant (blind
round 40's class; the round's own sentences were never read). Another's doing, a getting verb
and a bare "it" are read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.ward import ward

_frame = frame_reader(ward, "omar")


@pytest.mark.parametrize(
    "text",
    [
        "print the meeting note I just saved and bring it to me thx",
        "print the draft I sent you and bring it over",
        "can you print the spreadsheet that I made this morning and bring it to me",
        "print the handover notes I've written and bring them to me please",
        "pls print out the rota I had already typed up and drop it at my desk",
    ],
)
def test_the_speakers_own_doing_names_their_own_file(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "omar", "omar")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "print it and bring it over",
        "print the meeting note and bring it to me",
    ],
)
def test_nothing_said_that_it_could_be_is_still_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Which file" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "bring me the stapler I lent Zoe",
        "bring me the ruler Zoe lent me",
        "bring me the ruler I borrowed",
    ],
)
def test_a_thing_of_anothers_is_not_the_speakers(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "omar")], frame
    assert frame.tasks[0].owner != "omar", frame


def test_a_paper_noun_printed_is_the_requesters_file_where_the_office_has_no_paper() -> None:
    frame = _frame("print my draft")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("print", "file", "omar")], frame
