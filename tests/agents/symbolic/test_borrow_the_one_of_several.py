"""Borrowing "the X" where several colleagues have one and nothing says whose asks whose
(blind round 67's class: "can I borrow the book?" took one colleague's book, after their yes,
that nobody chose): "borrow" asks for one particular thing, lent by its owner, so it is read
like "take the X over to ..." (``several_owners``), naming the few who have one. "a book",
"any book", "someone's book", a thing the speaker has, a thing one colleague has, and "bring
me the book" (any one will do) are read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.stage_crew import stage_crew

_frame = frame_reader(stage_crew, "kit")


@pytest.mark.parametrize(
    "text",
    [
        "can I borrow the book?",
        "could I borrow the book please",
        "let me borrow the book",
        "could I borrow the book for an hour?",
    ],
)
def test_borrowing_the_one_of_several_asks_whose(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "whose" in frame.question and "Ana Ruiz" in frame.question, frame


def test_the_answer_names_the_owner() -> None:
    from helpers.reading import parser_for

    frame = parser_for(stage_crew).parse_with_answers("can I borrow the book?", "kit", ["Ana's"])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("book", "ana", "kit")], frame


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can I borrow a book?", "book", None),
        ("can I borrow any book?", "book", None),
        ("can I borrow someone's book?", "book", None),
        ("can I borrow the book from Sam?", "book", "sam"),
        ("bring me the book", "book", None),
        ("can I borrow the stapler?", "stapler", None),  # only Sam has one
    ],
)
def test_anyones_or_said_is_read_as_before(text: str, item: str, owner: str | None) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "kit")], frame


def test_the_speakers_own_kind_is_not_asked() -> None:
    frame = _frame("can I borrow the headset?")  # Kit has a headset
    assert frame.question is None, frame
