"""A second request said as a strong want: "would you bring me some tape? I'm also desperate
for a tea". An additive ("also", "still") among the degree words of a wanting idiom leaves it
the speaker's want, and the idioms said with "is" ("gasping for", "desperate for") are read of
a colleague's name too: that colleague's want. Nothing the office has ("the weekend", "a
holiday") stays words."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "bill")
_DEFAULT = frame_reader(default_office, "wu")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("would you bring me some tape? I'm also desperate for a tea.", "tape"),
        ("would you bring me some tape? I'm also dying for a tea", "tape"),
        ("would you bring me a ruler? I'm also gasping for a tea", "ruler"),
        ("would you bring me a ruler? I'm also in need of a tea", "ruler"),
        ("would you bring me a ruler? I could really do with a tea too", "ruler"),
    ],
)
def test_harbour_the_strong_want_is_a_second_request(text: str, first: str) -> None:
    frame = _HARBOUR(text)
    assert _tasks(frame) == [("transfer", first, "bill"), ("produce", "tea", "bill")], frame


@pytest.mark.parametrize(
    ("text", "first", "made"),
    [
        ("would you bring me a pen? I'm also desperate for a coffee.", "pen", "coffee"),
        ("could you grab me the stapler? I am also gasping for a water", "stapler", "water"),
        ("would you bring me a pen? we're still dying for some coffee", "pen", "coffee"),
    ],
)
def test_default_office_the_strong_want_is_a_second_request(
    text: str, first: str, made: str
) -> None:
    frame = _DEFAULT(text)
    assert _tasks(frame) == [("transfer", first, "wu"), ("produce", made, "wu")], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a pen? I'm desperate for the weekend",
        "bring me a pen? I'm also desperate for a holiday",
    ],
)
def test_nothing_the_office_has_stays_words(text: str) -> None:
    assert _tasks(_DEFAULT(text)) == [("transfer", "pen", "wu")]


def test_a_colleagues_strong_want_is_theirs() -> None:
    frame = _DEFAULT("would you bring me a pen? Zhang is desperate for a coffee")
    assert _tasks(frame) == [("transfer", "pen", "wu"), ("produce", "coffee", "zhang")], frame
    frame = _HARBOUR("bring me a ruler? Mark's also dying for a tea")
    assert _tasks(frame) == [("transfer", "ruler", "bill"), ("produce", "tea", "mark")], frame


def test_a_colleagues_strong_want_alone_is_asked_for_them() -> None:
    frame = _DEFAULT("Zhang is desperate for a coffee")
    assert not frame.tasks and frame.question is not None, frame
    assert "Zhang" in frame.question and "coffee" in frame.question, frame
