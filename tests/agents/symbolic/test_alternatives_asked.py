"""Two things offered as alternatives the speaker is unsure of ("the thing for cutting tape?
or the stapler, not sure which I need", "a ruler or maybe a calculator", "..., whichever") are
one question naming the options, never both fetched (fix180a class 5); "X and Y" is both."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "question"),
    [
        (
            _lee,
            "can you bring me the thing for cutting tape? or the stapler, not sure which I need",
            "Which would you like: the scissors or the stapler?",
        ),
        (
            _may,
            "can you bring me the thing for cutting tape? or the ruler, not sure which I need",
            "Which would you like: the tape dispenser or the ruler?",
        ),
        (
            _may,
            "can you bring me a ruler or maybe a calculator",
            "Which would you like: the ruler or the calculator?",
        ),
        (
            _lee,
            "bring me the stapler or the scissors, whichever",
            "Which would you like: the stapler or the scissors?",
        ),
        (
            _lee,
            "bring me a pen? or a stapler, not sure which I need",
            "Which would you like: the pen or the stapler?",
        ),
    ],
)
def test_alternatives_are_asked(read: Any, text: str, question: str) -> None:
    frame = read(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question == question, frame


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("bring me a pen and a stapler", ["pen", "stapler"]),
        # the same kind named twice is one thing
        (
            "can you bring me the thing for cutting tape? or the scissors, not sure which",
            ["scissors"],
        ),
    ],
)
def test_both_or_one_kind_are_unchanged(text: str, items: list[str]) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.item for t in frame.tasks] == items, frame
