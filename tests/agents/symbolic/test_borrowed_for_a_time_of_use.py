"""A time said after "for" is when a borrowed thing is used, not when it is handed over
(class 86m-2): "anyone got a stapler i can nab for tonight? workshop at 9" was not understood,
and "... i can borrow for tonight?" was answered as a need for later. Borrowed for tonight is
had by tonight, so brought now (anyone's, with the owner's yes), as an event's time already
is ("for the review at 2", reading/future_need.without_events). A time said without "for"
("... i could borrow later?") still puts the borrowing off, and "who has a stapler?" is still
answered."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "mark")


def _brought_to_speaker(frame: TaskFrame, item: str, speaker: str) -> bool:
    return frame.understood and [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", item, speaker)
    ]


@pytest.mark.parametrize(
    "text",
    [
        "anyone got a stapler i can nab for tonight? workshop at 9",
        "anyone got a stapler i can borrow for tonight? workshop at 9",
        "anyone got a stapler i can borrow for tonight?",
        "anyone got a stapler i can pinch for later?",
        "anyone got a stapler i can nab for the weekend?",
    ],
)
def test_default_borrowed_for_a_later_use_is_brought_now(text: str) -> None:
    frame = _default(text)
    assert _brought_to_speaker(frame, "stapler", "mao"), frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("anyone got a ruler i can pinch for tonight? meeting at 7", "ruler"),
        ("anyone got a calculator i can borrow for tomorrow?", "calculator"),
        ("anyone got a highlighter i can nab for later on?", "highlighter"),
    ],
)
def test_harbour_borrowed_for_a_later_use_is_brought_now(text: str, item: str) -> None:
    frame = _harbour(text)
    assert _brought_to_speaker(frame, item, "mark"), frame


@pytest.mark.parametrize(
    "text",
    [
        "does anyone have a stapler i could borrow later?",
        "anyone got a stapler i could nab later?",
    ],
)
def test_a_borrowing_said_for_later_without_for_waits(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "Tell me when you need it" in frame.decline


def test_who_has_one_is_answered() -> None:
    frame = _default("who has a stapler?")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "have a stapler" in frame.question


def test_a_hand_over_said_for_tonight_keeps_its_reading() -> None:
    # the time without "for" is when it is wanted; read as before (brought)
    frame = _default("bring me a stapler tonight")
    assert _brought_to_speaker(frame, "stapler", "mao"), frame
