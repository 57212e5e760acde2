"""A part of a message that names a thing the office has no name for ("my lamp", "a lamp") is
never dropped in silence (``reading.unnamed_things``, asked by ``parts.unread_part``): "take
my lamp to Rose, and bring me Grace's highlighter" in harbour (no lamp) did the highlighter
alone and said "Done"; "bring me Grace's highlighter and take my lamp to Rose" even gave the
highlighter to Rose. The part is asked about before anything moves, whichever order the parts
come in; an answer naming a thing of the office does both; "I don't know" keeps it asked,
nothing done. A statement or reason beside a request ("- mine's broken") is not affected."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_harbour = frame_reader(harbour_office, "will")
_default = frame_reader(default_office, "zhang")
_harbour_answered = answered_reader(harbour_office, "will")
_DONT_KNOW = "Sorry, I don't know more than I wrote."


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "phrase"),
    [
        # the class's analogue, and the same parts the other way round
        ("harbour", "take my lamp to Rose, and bring me Grace's highlighter", "my lamp"),
        ("harbour", "bring me Grace's highlighter and take my lamp to Rose", "my lamp"),
        # variants of our own: other verbs, joins, things, owners, offices
        ("harbour", "could you take my lamp over to Rose and then bring me a ruler", "my lamp"),
        ("harbour", "bring Rose my lamp and bring me a calculator", "my lamp"),
        ("harbour", "bring me Mark's old toolbox and a ruler", "Mark's old toolbox"),
        ("default", "take my laptop to Lee and bring me Chen's scissors", "my laptop"),
        ("default", "bring me a stapler and take my hat to Wang", "my hat"),
        ("default", "print my file and take my laptop to Lee", "my laptop"),
        # said with an article, not whose it is
        ("harbour", "take a lamp to Rose, and bring me Grace's highlighter", "a lamp"),
        ("harbour", "take the lamp to Rose and bring me a ruler", "the lamp"),
        ("default", "bring me a stapler and take the projector to Wang", "the projector"),
    ],
)
def test_the_part_with_an_unnamed_thing_is_asked_before_anything_moves(
    office: str, text: str, phrase: str
) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None and f"“{phrase}”" in frame.question, frame.question


def test_an_answer_naming_a_thing_of_the_office_does_both_parts() -> None:
    frame = _harbour_answered(
        "take my lamp to Rose, and bring me Grace's highlighter", ["my calculator"]
    )
    assert sorted(_tasks(frame), key=str) == sorted(
        [
            ("transfer", "calculator", "will", "rose"),
            ("transfer", "highlighter", "grace", "will"),
        ],
        key=str,
    )


def test_an_answer_to_a_thing_said_with_an_article_takes_its_place() -> None:
    frame = _harbour_answered("take the lamp to Rose and bring me a ruler", ["the calculator"])
    assert sorted(_tasks(frame), key=str) == sorted(
        [("transfer", "calculator", "will", "rose"), ("transfer", "ruler", None, "will")], key=str
    ), frame.question


def test_no_answer_leaves_it_asked_and_nothing_done() -> None:
    frame = _harbour_answered(
        "take my lamp to Rose, and bring me Grace's highlighter", [_DONT_KNOW, _DONT_KNOW]
    )
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None and "“my lamp”" in frame.question, frame.question


@pytest.mark.parametrize(
    ("office", "text", "expected"),
    [
        # must not change: a reason or statement beside the request, things the office names
        (
            "harbour",
            "bring me Grace's highlighter - mine's broken",
            [("transfer", "highlighter", "grace", "will")],
        ),
        (
            "harbour",
            "bring me Grace's highlighter, my lamp is broken",
            [("transfer", "highlighter", "grace", "will")],
        ),
        (
            "harbour",
            "bring me Grace's highlighter and a ruler",
            [("transfer", "highlighter", "grace", "will"), ("transfer", "ruler", None, "will")],
        ),
        (
            "default",
            "take my stapler to Lee and bring me Chen's scissors",
            [("transfer", "stapler", "zhang", "lee"), ("transfer", "scissors", "chen", "zhang")],
        ),
    ],
)
def test_neighbours_keep_their_reading(
    office: str, text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    frame = _read(office, text)
    assert _tasks(frame) == expected, (frame.question, frame.decline)
