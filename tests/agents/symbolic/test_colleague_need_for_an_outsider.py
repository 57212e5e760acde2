"""A colleague named as needing the thing is its recipient; an outsider after "for" in the
same message is what it is for (class 93d-2, ``screen.colleague_need``): "mark needs my ruler
for a student on his course, could you take it over" takes the ruler to Mark instead of
asking "I don't know who a student is". With no colleague who needs it ("my ruler is for a
student, take it to reception") or with the outsider as the recipient ("take it to the
student") the ask stands."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item", "recipient", "owner"),
    [
        (
            "harbour",
            "mark needs my ruler for a student on his course, could you take it over",
            "ruler",
            "mark",
            "rose",
        ),
        (
            "default",
            "wang needs my stapler for a client meeting, could you take it over",
            "stapler",
            "wang",
            "lee",
        ),
        # variants of our own: other need phrases and outsiders
        (
            "harbour",
            "will needs my calculator for a child in his group, can you take it to him",
            "calculator",
            "will",
            "rose",
        ),
        (
            "default",
            "zhang could use my stapler for a customer of his, please take it over",
            "stapler",
            "zhang",
            "lee",
        ),
    ],
)
def test_the_colleague_who_needs_it_receives_it(
    office: str, text: str, item: str, recipient: str, owner: str
) -> None:
    frame = _read(office, text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient, t.owner) for t in frame.tasks] == [
        ("transfer", item, recipient, owner)
    ], frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("harbour", "my ruler is for a student, take it to reception"),
        ("default", "my stapler is for a client, take it to reception"),
        ("harbour", "mark needs my ruler, take it to the student"),
    ],
)
def test_no_colleague_in_need_still_asks(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [] and frame.question is not None, frame


def test_the_outsider_as_recipient_is_still_asked_about() -> None:
    frame = _harbour("mark needs my ruler, take it to the student")
    assert frame.question is not None and "the student" in frame.question, frame
