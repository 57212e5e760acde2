"""A colleague's thing asked for the speaker, then referred back to as another colleague's
need ("could I have Wang's budget plan? Zhang needs the file"): the later "the file"/"it" is
the colleague's thing, never the speaker's own, and the two recipients differ, so the reader
asks for whom before anything moves; the answer decides (``reading.back_reference_recipient``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_DEFAULT_ANSWERED = answered_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")
_HARBOUR_ANSWERED = answered_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str, str | None, str | None]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "question"),
    [
        # the class's analogue: Wang's, for Lee or for Zhang? (was Lee's own file to Zhang)
        (
            "could I have Wang's budget plan? Zhang needs the file",
            "Wang's budget plan file for you, or for Zhang Wei?",
        ),
        ("could I have Wang's file? Zhang needs it", "Wang's file for you, or for Zhang Wei?"),
        (
            "could I have Wang's report? Zhang needs the report",
            "Wang's report for you, or for Zhang Wei?",
        ),
        # the recipient after "to", and a want said with a helping verb
        (
            "could I have Wang's budget plan? send the file to Zhang",
            "Wang's budget plan file for you, or for Zhang Wei?",
        ),
        (
            "could I have Wang's budget plan? Zhang would like the file",
            "Wang's budget plan file for you, or for Zhang Wei?",
        ),
        (
            "can you send me Hu's quarterly forecast? Zhang wants the file",
            "Hu's quarterly forecast for you, or for Zhang Wei?",
        ),
    ],
)
def test_default_office_asks_for_whom(text: str, question: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question == question, frame
    assert not frame.tasks


@pytest.mark.parametrize(
    ("text", "question"),
    [
        (
            "could I have Mark's crane lift plan? Rose needs the file",
            "Mark's crane lift plan file for you, or for Rose Adeyemi?",
        ),
        (
            "can I get Pat's contract? Bill needs it",
            "Pat's contract for you, or for Bill Ferreira?",
        ),
    ],
)
def test_harbour_asks_for_whom(text: str, question: str) -> None:
    assert _HARBOUR(text).question == question, _HARBOUR(text)


@pytest.mark.parametrize(
    ("answer", "recipient"),
    [("For Zhang Wei.", "zhang"), ("Zhang", "zhang"), ("For me, please.", "lee")],
)
def test_the_answer_says_whom_and_the_thing_stays_wangs(answer: str, recipient: str) -> None:
    frame = _DEFAULT_ANSWERED("could I have Wang's budget plan? Zhang needs the file", [answer])
    assert _tasks(frame) == [("send_file", "file", "wang", recipient)], frame


def test_harbour_answer_for_the_other_carries_the_owners_paper() -> None:
    frame = _HARBOUR_ANSWERED("can I get Pat's contract? Bill needs it", ["For Bill."])
    assert _tasks(frame) == [("transfer", "document", "pat", "bill")], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the same recipient said again: nothing to ask
        (
            "could I have Wang's budget plan? just send me the file",
            [("send_file", "file", "wang", "lee")],
        ),
        # negated: Zhang is no recipient
        ("could I have Wang's file? Zhang doesn't need it", [("send_file", "file", "wang", "lee")]),
        # the thing asked for the other from the start: nobody to choose between
        ("get Wang's budget plan file for Zhang", [("send_file", "file", "wang", "zhang")]),
    ],
)
def test_must_not_change_neighbours(
    text: str, expected: list[tuple[str, str, str | None, str | None]]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None and _tasks(frame) == expected, frame


def test_my_own_thing_named_for_the_other_is_no_back_reference() -> None:
    # "my file" is said, not referred back to: Lee's own file goes to Zhang as asked
    frame = _DEFAULT("could I have Wang's report? Zhang needs my file")
    assert frame.question is None or "or for Zhang" not in frame.question, frame
