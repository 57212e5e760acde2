"""The parts of an announced list are each asked for: "2 things: my report printed, and
Wang's stapler if he's not using it" printed the report and dropped the borrowing in silence
(the count "2" was not read as a count, and a note-form part has no verb of asking). After
"N things:" / "two things -", each part that is a noun phrase (with or without a participle)
and states nothing is the speaker's need. Parts that state something ("the printer's jammed")
stay statements, and "2 things I noticed: ..." announces no list."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "2 things: my report printed, and Wang's stapler if he's not using it",
            [("print", "file", "lin", "lin"), ("transfer", "stapler", "lin", "wang")],
        ),
        (
            "two things - a coffee, and Zhang's stapler",
            [("produce", "coffee", "lin", None), ("transfer", "stapler", "lin", "zhang")],
        ),
        (
            "two things - my contract signed by Wang, and a coffee",
            [("sign", "document", "lin", "lin"), ("produce", "coffee", "lin", None)],
        ),
        (
            "3 things: a coffee, some water and Wang's stapler. Thanks!",
            [
                ("produce", "coffee", "lin", None),
                ("produce", "water", "lin", None),
                ("transfer", "stapler", "lin", "wang"),
            ],
        ),
        (
            "a couple of things - my report printed and my contract copied",
            [("print", "file", "lin", "lin"), ("copy", "document", "lin", "lin")],
        ),
    ],
)
def test_each_listed_part_is_asked_for(
    text: str, tasks: list[tuple[str, str, str, str | None]]
) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient, t.owner) for t in frame.tasks] == tasks


def test_the_same_on_harbour() -> None:
    frame = _harbour("2 things: my report printed, and Mark's ruler if he's not using it")
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [
        ("print", "file", "will"),
        ("transfer", "ruler", "mark"),
    ]


def test_parts_with_a_verb_are_left_as_said() -> None:
    frame = _default("Two things: take my book to Wang, and I need a coffee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "book", "wang"),
        ("produce", "coffee", "lin"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "2 things I noticed: the printer's jammed and the kitchen's out of milk",
        "2 things: the printer's jammed and the kitchen's out of milk",
    ],
)
def test_listed_statements_ask_for_nothing(text: str) -> None:
    """Neighbour: statements of how things are move nothing."""
    assert _default(text).tasks == []
