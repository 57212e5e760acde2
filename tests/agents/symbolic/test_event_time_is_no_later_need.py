"""A time of the event a thing is for says by when it is needed, so it is needed now, in a
question that asks to borrow it as in "I need ..." (test_future_need.py): "anyone got a
stapler i can borrow for the review at 2?" brings one (a colleague's, with their yes); before,
"at 2" was read as a later need and it was answered with "Tell me when you need it". A time
for the hand-over itself ("can I borrow a stapler at 2?", "... borrow at 2 for the review?")
and a later day ("... I can borrow tomorrow?") are read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "pat")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        ("default", "anyone got a stapler i can borrow for the review at 2?", "stapler"),
        ("default", "does anyone have a stapler I could borrow for the meeting at 3?", "stapler"),
        ("default", "anyone got a pen i can borrow for my 3pm call?", "pen"),
        ("harbour", "anyone got a ruler I can borrow for the workshop at 4?", "ruler"),
        (
            "harbour",
            "does anybody have a calculator i could use for the audit at half two?",
            "calculator",
        ),
        ("default", "I need a stapler for the review at 2", "stapler"),  # the need's form agrees
    ],
)
def test_an_event_time_asks_for_the_thing_now(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("default", "anyone got a stapler i can borrow tomorrow?"),
        ("default", "anyone got a stapler i can borrow at 2 for the review?"),
        ("harbour", "does anyone have a ruler I could borrow at 4?"),
        ("default", "does anyone have a stapler I could borrow for the afternoon at 2?"),
        # the asking put off in so many words: the event's time waits for the word
        ("default", "could I borrow a stapler for the meeting at 3? I'll let you know"),
    ],
)
def test_a_time_for_the_hand_over_is_still_later(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame.tasks


@pytest.mark.parametrize(
    ("text", "item"),
    [("can I borrow a stapler at 2?", "stapler"), ("bring me a stapler at 3pm", "stapler")],
)
def test_a_request_with_a_time_is_read_as_before(text: str, item: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)]


def test_who_has_one_is_answered() -> None:
    frame = _default("who has a stapler?")
    assert frame.tasks == []
