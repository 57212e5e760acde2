"""A combination whose second part is elliptical ("pls drop my stapler at Zhang's desk, and a
coffee for me on the way back"): the second part's "on the way back" is an aside that joins it
to the errand before it (``request_asides``), not a surface the coffee was spilt on
(``screen.on_a_thing._aside_at``), so both parts are done. "coffee on my keyboard again" is
still a mess told. On the default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "first", "second"),
    [
        (
            "pls drop my stapler at Zhang's desk, and a coffee for me on the way back",
            ("transfer", "stapler", "lee", "zhang"),
            ("produce", "coffee", None, "lee"),
        ),
        (
            "drop my scissors at Chen's desk, and a coffee for me on the way back",
            ("transfer", "scissors", "lee", "chen"),
            ("produce", "coffee", None, "lee"),
        ),
        (
            "take my book to Wang Fang, and some water for me on your way back",
            ("transfer", "book", "lee", "wang"),
            ("produce", "water", None, "lee"),
        ),
        (
            "bring my stapler to Zhang, and a coffee for Chen on the way back",
            ("transfer", "stapler", "lee", "zhang"),
            ("produce", "coffee", None, "chen"),
        ),
    ],
)
def test_default_office_both_parts_are_done(
    text: str, first: tuple[str, str, str | None, str], second: tuple[str, str, None, str]
) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [first, second]


@pytest.mark.parametrize(
    ("text", "first", "second"),
    [
        (
            "pls drop my ruler at Mark's desk, and a tea for me on the way back",
            ("transfer", "ruler", "pat", "mark"),
            ("produce", "tea", None, "pat"),
        ),
        (
            "take my calculator to Grace, and a notepad for me on your way past",
            ("transfer", "calculator", "pat", "grace"),
            ("produce", "notepad", None, "pat"),
        ),
    ],
)
def test_harbour_both_parts_are_done(
    text: str, first: tuple[str, str, str | None, str], second: tuple[str, str, None, str]
) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [first, second]


@pytest.mark.parametrize(
    "text", ["coffee on my keyboard again", "take my stapler to Zhang, coffee on my keyboard again"]
)
def test_a_thing_spilt_on_another_is_still_told(text: str) -> None:
    """Neighbour: "on my keyboard" is a surface, no aside: nothing is made."""
    frame = _default(text)
    assert all(t.item != "coffee" for t in frame.tasks), _tasks(frame)
