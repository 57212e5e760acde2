"""The item named in answer to "Which item do you mean …?" takes the place of the noun the
request said but the office does not know (blind round 61's class: "send my signed statement
by courier to …" in an office whose paper is not called a statement; the answer "The
document." was read as a sentence of its own, lost the request's "my", and the reader asked
"Whose document do you mean?" until the request failed)."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(courier_room, "bjorn")
_answered = answered_reader(courier_room, "bjorn")


@pytest.mark.parametrize(
    ("text", "answer", "owner"),
    [
        ("send my signed affidavit by courier to Crown Court", "The document.", "bjorn"),
        ("could you send my affidavit by courier to Crown Court?", "the document", "bjorn"),
        ("could you courier our affidavit to Crown Court?", "A document.", "bjorn"),
        # the answer says whose: its owner with it (asked for consent where the work runs)
        ("courier the affidavit to Crown Court", "my contract", "bjorn"),
        ("courier the affidavit to Crown Court", "Ana's contract", "ana"),
    ],
)
def test_the_answer_names_the_thing_the_request_said(text: str, answer: str, owner: str) -> None:
    assert _frame(text).question is not None and _frame(text).question.startswith(
        "Which item do you mean"
    )
    frame = _answered(text, [answer])
    assert [(t.operation, t.item, t.owner, t.destination) for t in frame.tasks] == [
        ("courier", "document", owner, "Crown Court")
    ], frame


def test_an_answer_that_names_no_item_is_asked_again() -> None:
    frame = _answered("send my signed affidavit by courier to Crown Court", ["not sure"])
    assert not frame.understood and frame.question is not None, frame
