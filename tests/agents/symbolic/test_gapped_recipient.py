"""A giving verb's recipient said again after "and", the verb left unsaid ("bring Wang a
coffee and Sun a water"), is the next object's recipient, never the first's
(``reading.gapped_recipient``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "bring Wang a coffee and Sun a water",  # the class's neighbour: two parts
            [("produce", "coffee", None, "wang"), ("produce", "water", None, "sun")],
        ),
        (
            "get me a coffee and Wang a water",
            [("produce", "coffee", None, "lee"), ("produce", "water", None, "wang")],
        ),
        (
            "get Wang my stapler and Sun a coffee",
            [("produce", "coffee", None, "sun"), ("transfer", "stapler", "lee", "wang")],
        ),
    ],
)
def test_default_each_part_has_its_own_recipient(
    text: str, tasks: list[tuple[str, str, str, str]]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "bring Mark a tea and Rose a ruler",
            [("produce", "tea", None, "mark"), ("transfer", "ruler", None, "rose")],
        ),
        (
            "get Pat a tea and me a highlighter",
            [("produce", "tea", None, "pat"), ("transfer", "highlighter", None, "will")],
        ),
        (
            "bring me a tea and Pat a ruler",
            [("produce", "tea", None, "will"), ("transfer", "ruler", None, "pat")],
        ),
    ],
)
def test_harbour_each_part_has_its_own_recipient(
    text: str, tasks: list[tuple[str, str, str, str]]
) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


@pytest.mark.parametrize(
    "text",
    [
        "bring Wang a coffee and her a water",  # "her" is someone besides Wang: whom?
        "Sun is thirsty, make Mao a coffee and her a water",
    ],
)
def test_a_pronoun_of_the_gap_besides_the_first_recipient_is_asked(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and "'her'" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # neighbours: no second recipient, both things to the one named
        (
            "bring Wang a coffee and a water",
            [("produce", "coffee", None, "wang"), ("produce", "water", None, "wang")],
        ),
        (
            "bring Wang a coffee and Sun's stapler",
            [("produce", "coffee", None, "wang"), ("transfer", "stapler", "sun", "wang")],
        ),
        ("bring Wang a coffee and Sun said hi", [("produce", "coffee", None, "wang")]),
    ],
)
def test_no_gap_is_unchanged(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


def test_a_gap_with_no_object_of_the_office_takes_no_object() -> None:
    """ "bring Mark a tea and Rose a water" where the office has no water: the tea is still
    Mark's (Rose is no recipient of the tea)."""
    frame = _HARBOUR("bring Mark a tea and Rose a water")
    assert ("produce", "tea", None, "mark") in _tasks(frame), frame
    assert all(t.recipient != "rose" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "office", "expected"),
    [
        # the subject of a need after "and" is the next object's, not the one's before
        (
            "take my stapler to Wang and Sun needs a coffee",
            "default",
            [("produce", "coffee", None, "sun"), ("transfer", "stapler", "lee", "wang")],
        ),
        (
            "bring my stapler to Wang and Sun wants a water",
            "default",
            [("produce", "water", None, "sun"), ("transfer", "stapler", "lee", "wang")],
        ),
        (
            "take my ruler to Mark and Rose needs a tea",
            "harbour",
            [("produce", "tea", None, "rose"), ("transfer", "ruler", "will", "mark")],
        ),
    ],
)
def test_a_need_said_after_and_is_the_next_objects(
    text: str, office: str, expected: list[tuple[str, str, str, str]]
) -> None:
    frame = (_DEFAULT if office == "default" else _HARBOUR)(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(expected), frame


@pytest.mark.parametrize(
    ("text", "office", "first", "second"),
    [
        # "needs" left unsaid the second time: restated as made-from-nothing parts are, each
        # thing for its own person
        ("Wang needs my stapler and Sun a coffee", "default", "Wang Fang", "Sun Li"),
        ("Wang wants a coffee and Sun a water", "default", "Wang Fang", "Sun Li"),
        ("Mark needs a ruler and Rose a tea", "harbour", "Mark Lindqvist", "Rose Adeyemi"),
    ],
)
def test_a_need_left_unsaid_after_and(text: str, office: str, first: str, second: str) -> None:
    frame = (_DEFAULT if office == "default" else _HARBOUR)(text)
    assert frame.question is not None, frame
    at_first, at_second = frame.question.find(first), frame.question.find(second)
    assert 0 <= at_first < at_second, frame
    assert frame.question.count(first) == 1, frame


def test_one_in_need_of_two_things_gets_both() -> None:
    """Neighbour: "Wang needs a stapler and a coffee": no second person, both for Wang."""
    frame = _DEFAULT("Wang needs a stapler and a coffee")
    assert frame.question is not None and frame.question.count("Wang Fang") == 2, frame
