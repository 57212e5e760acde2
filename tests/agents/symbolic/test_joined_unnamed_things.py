"""A second noun with no verb of its own shares the verb before it (class 72j-3): "bring me a
stapler and the projector" (default office; no projector there) did the stapler alone. A
thing joined by "and" to a requested thing is asked about before anything moves when no name
of the office reads it (``unnamed_things._joined_thing``), and done when it is known."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "zhang")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        ("bring me a stapler and the projector", "the projector"),
        ("bring Lee a pen and a lamp", "a lamp"),
        ("bring me a stapler and a book and a lamp", "a lamp"),
        ("bring me a stapler and scissors and a torch", "a torch"),
        ("take my stapler to Lee and the projector to Wang", "the projector"),
    ],
)
def test_an_unknown_thing_joined_to_a_requested_one_is_asked_about(text: str, phrase: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        ("fetch me a ruler and the projector please", "the projector"),
        ("bring me a ruler and a lamp, then make Mark a tea", "a lamp"),
    ],
)
def test_on_harbour_too(text: str, phrase: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("bring me a stapler and scissors", ["stapler", "scissors"]),
        ("bring me a stapler and a book", ["stapler", "book"]),
    ],
)
def test_known_things_joined_are_both_done(text: str, items: list[str]) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", i, "zhang") for i in items
    ]


def test_a_joined_clause_of_its_own_is_no_thing() -> None:
    # "and the meeting starts at 3" has its own verb: no thing to move
    frame = _default("bring me a stapler and the meeting starts at 3")
    assert frame.question is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]


def test_a_ruler_and_a_highlighter_for_a_colleague() -> None:
    frame = _harbour("bring Rose a ruler and a highlighter")
    assert frame.question is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [
        ("ruler", "rose"),
        ("highlighter", "rose"),
    ]


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        # no errand's verb: the things are joined all the same (the tea was made and the
        # biscuit never mentioned)
        ("a tea and a biscuit please", "a biscuit"),
        ("can I have a tea and a biscuit", "a biscuit"),
        ("a ruler and some biscuits please", "some biscuits"),
        # a word no dictionary knows, after an article, is a thing's name all the same
        ("a tea and some paperclips please", "some paperclips"),
        ("fetch me a ruler and some paperclips", "some paperclips"),
    ],
)
def test_an_unknown_thing_joined_with_no_verb_is_asked_about(text: str, phrase: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("a tea and a ruler please", ["tea", "ruler"]),
        ("a tea please and the meeting starts at 3", ["tea"]),
    ],
)
def test_known_things_with_no_verb_are_done(text: str, items: list[str]) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame
    assert [t.item for t in frame.tasks] == items


def test_a_statement_of_things_had_asks_nothing() -> None:
    frame = _harbour("I had a tea and a biscuit")
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("bring me some paperclips", "there are no paperclips in this office"),
        ("bring me some biscuits", "so I can't get you any."),
        ("bring me a tape measure", "there is no tape measure in this office"),
    ],
)
def test_an_unknown_thing_is_declined_in_its_number(text: str, said: str) -> None:
    frame = _harbour(text)
    assert frame.decline is not None and said in frame.decline, frame
