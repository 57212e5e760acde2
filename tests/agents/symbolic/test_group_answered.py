"""The answer to "Should the stapler go to Wang Fang, or to Sun Li?" names whom the one thing
goes to; an answer naming neither leaves the question open (``reading.group_answered``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader

_DEFAULT = answered_reader(default_office, "lee")
_HARBOUR = answered_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "answer", "item", "owner", "recipient"),
    [
        ("Wang and Sun need a stapler", "Wang", "stapler", None, "wang"),
        ("Wang and Sun need a stapler", "to Sun please", "stapler", None, "sun"),
        ("take the book to Wang and Sun", "Sun", "book", "lee", "sun"),
        ("give Wang and Sun my stapler", "Wang", "stapler", "lee", "wang"),
    ],
)
def test_default_the_answer_names_the_one(
    text: str, answer: str, item: str, owner: str | None, recipient: str
) -> None:
    frame = _DEFAULT(text, [answer])
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "answer", "owner", "recipient"),
    [
        ("Rose and Mark need a ruler", "Mark", None, "mark"),
        ("take my ruler to Rose and Mark", "Rose", "will", "rose"),
    ],
)
def test_harbour_the_answer_names_the_one(
    text: str, answer: str, owner: str | None, recipient: str
) -> None:
    frame = _HARBOUR(text, [answer])
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", owner, recipient)
    ], frame


def test_an_answer_naming_neither_leaves_it_asked() -> None:
    frame = _DEFAULT("Wang and Sun need a stapler", ["Mao"])
    assert frame.tasks == [], frame
    assert frame.question is not None and "Wang Fang, or to Sun Li?" in frame.question
