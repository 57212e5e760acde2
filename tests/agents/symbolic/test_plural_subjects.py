"""A plural subject with its plain verb is told, not asked ("The new lights make the drill bay
look so bright." fetched a drill: found by fixer E this stop, as the singular "the new light
makes ..." was already read as a statement). A command opens with its verb, and a request
beside the statement is read as before."""

from __future__ import annotations

import pytest

from helpers.drill_shed import drill_shed
from helpers.reading import frame_reader

_frame = frame_reader(drill_shed, "sunny")


@pytest.mark.parametrize(
    "text",
    [
        "The new lights make the drill bay look so bright.",
        "These new drills make a lot of noise.",
        "the lights make the drill look new",
    ],
)
def test_a_plural_subjects_verb_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("the drills make my headset buzz, can you bring me another headset", "headset"),
        ("make sure the drill gets to me", "drill"),
        ("I have faith in you bring me a drill", "drill"),
    ],
)
def test_a_request_beside_it_or_a_command_reads_as_before(text: str, item: str) -> None:
    frame = _frame(text)
    assert [t.item for t in frame.tasks] == [item], frame
