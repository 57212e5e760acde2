"""The speaker's "I'm after X" / "we're after X" is their need of X, as "Kit's after a torch" is
Kit's (fix93e class 1: "I'm after a calculator" was read as a statement and moved nothing).
"after" wants only before an article or a quantity, so "I'm after the meeting" and "I'll do it
after lunch" stay times and move nothing."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "rose")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I'm after a calculator", "calculator"),
        ("im after a ruler, mine is snapped", "ruler"),
        ("I am really after a highlighter", "highlighter"),
        ("we're after a tape dispenser", "tape"),
    ],
)
def test_the_speaker_after_a_thing_needs_it_in_harbour(text: str, item: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "rose")]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I'm after a stapler", "stapler"),
        ("we're after some paper", "paper"),
        ("im just after a pen, mine ran dry", "pen"),
    ],
)
def test_the_speaker_after_a_thing_needs_it_in_the_default_office(text: str, item: str) -> None:
    frame = _default(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "lee")]


@pytest.mark.parametrize(
    "text",
    ["I'm after the meeting", "I'll do it after lunch", "I'm free after the standup"],
)
def test_after_a_time_wants_nothing(text: str) -> None:
    assert _harbour(text).tasks == [] and _default(text).tasks == []
