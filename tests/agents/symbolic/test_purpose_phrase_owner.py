"""An owner named in a "for" purpose phrase after a request ("I need a copy of my report for
the owner's file") says what the thing is for, never whom it goes to (fix121a class 4). A
relational word the office's own people are also called by ("owner", "supervisor") is no
colleague there: the phrase's article and lower case make it a kind of person, as "the
client's file" already was. Its thing is the speaker's, worked on and handed to them. A
colleague named after "for" still receives, and the same words outside a "for" phrase are
still asked about."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "who"),
    [
        (_lin, "I need a photocopy of my report for the owner's file", "lin"),
        (_lin, "I need a copy of my report for the supervisor's file", "lin"),
        (_lin, "I need a copy of my report for the client's file", "lin"),
        (_may, "I need a scan of my claim form for the owner's file", "may"),
        (_may, "I need a scan of my claim form for the supervisor's file", "may"),
    ],
)
def test_an_owner_in_a_purpose_phrase_is_context(read: ReadFrame, text: str, who: str) -> None:
    frame = read(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", who, who)
    ], frame


@pytest.mark.parametrize(
    ("read", "text", "owner", "recipient"),
    [
        (_lin, "I need a copy of my report for Wang", "lin", "wang"),
        (_may, "I need a scan of my claim form for Mark", "may", "mark"),
    ],
)
def test_a_colleague_after_for_still_receives(
    read: ReadFrame, text: str, owner: str, recipient: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", owner, recipient)
    ], frame


@pytest.mark.parametrize(
    "text", ["bring me the owner's stapler", "bring me the supervisor's stapler"]
)
def test_the_same_word_outside_a_purpose_phrase_is_still_asked(text: str) -> None:
    frame = _lin(text)
    assert frame.tasks == [] and frame.question is not None, frame
