"""A colleague's possessive said as a place after "to" (fixer 82f, class 1): "bring the stapler
back to Wang's" and "could you take this book to Wang's if he's in" read two tasks, anyone's
thing AND the colleague's, both brought to the speaker (a wrong physical action). "to Wang's"
with no noun of its own is Wang's desk: Wang receives the thing, read as "to Wang" is
(``reading/possessive_place.py``). A noun after it, a possessive offered as a choice, and one
asked for ("bring me Wang's stapler") read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _same(one: TaskFrame, other: TaskFrame) -> None:
    assert one.tasks == other.tasks, (one, other)
    assert one.question == other.question, (one, other)


@pytest.mark.parametrize(
    ("said", "plain"),
    [
        # the class's analogues
        ("bring the stapler back to Wang's", "bring the stapler back to Wang"),
        ("could you take this book to Wang's if he's in", "could you take this book to Wang"),
        # variants: other verbs, people, things, what follows the possessive
        ("take the scissors to Zhang's, thanks", "take the scissors to Zhang, thanks"),
        ("bring the book back to Wang Fang's please", "bring the book back to Wang Fang please"),
        ("pls take my stapler over to Wang's when he's back", "pls take my stapler to Wang"),
    ],
)
def test_to_a_possessive_is_to_its_owner_default(said: str, plain: str) -> None:
    frame = _default(said)
    assert not any(t.recipient == "mao" for t in frame.tasks), frame
    _same(frame, _default(plain))


@pytest.mark.parametrize(
    ("said", "plain"),
    [
        ("take the ruler over to Pat's", "take the ruler over to Pat"),
        ("bring the ruler back to Pat's", "bring the ruler back to Pat"),
        ("could you run this notepad round to Pat's when she's free", "run this notepad to Pat"),
    ],
)
def test_to_a_possessive_is_to_its_owner_harbour(said: str, plain: str) -> None:
    frame = _harbour(said)
    assert not any(t.recipient == "may" for t in frame.tasks), frame
    _same(frame, _harbour(plain))


def test_one_task_for_this_book_to_wang() -> None:
    frame = _default("could you take this book to Wang's if he's in")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("book", None, "wang")]


@pytest.mark.parametrize(
    "text",
    [
        # neighbours: the possessive is whose thing, asked for or offered as the choice
        "bring me Wang's stapler",
        "can I have a stapler, Wang's if he's not using it",
        "bring me Wang's stapler please",
    ],
)
def test_a_possessive_asked_for_is_still_whose(text: str) -> None:
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "mao")], (
        frame
    )


def test_a_noun_after_the_possessive_is_left_to_the_frames() -> None:
    frame = _default("take my stapler to Wang's desk")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "mao", "wang")]
