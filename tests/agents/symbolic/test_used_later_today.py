"""A question for a thing the asker can use (or needs) at a time later the same day asks for
it now (class 93d-4, ``reading.used_today``): "anyone got a calculator i can use this
afternoon" brings one instead of "Tell me when you need it". A time on another day ("...
tomorrow", "next week"), "later" alone, and a time of the hand-over ("... I could borrow this
afternoon?") still wait, as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.used_today import used_later_today
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item", "recipient"),
    [
        ("harbour", "anyone got a calculator i can use this afternoon", "calculator", "rose"),
        ("default", "does anyone have scissors I could use later today", "scissors", "lee"),
        # variants of our own: other things, times and verbs
        ("harbour", "anyone got a calculator i could use later today?", "calculator", "rose"),
        ("default", "anyone got a stapler i can use tonight?", "stapler", "lee"),
        ("harbour", "does anyone have a ruler i could use this evening?", "ruler", "rose"),
    ],
)
def test_a_use_later_today_is_brought_now(
    office: str, text: str, item: str, recipient: str
) -> None:
    frame = _read(office, text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", item, recipient)
    ], frame


def test_a_need_later_today_is_offered_for_now() -> None:
    frame = _default("does anyone have scissors I need this afternoon?")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.endswith("Shall I bring you one?"), frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("harbour", "anyone got a calculator i can use tomorrow"),
        ("default", "does anyone have scissors I could use next week"),
        ("default", "does anyone have scissors I need tomorrow?"),
        ("default", "does anyone own a stapler I could use later?"),
        ("harbour", "does anyone have a ruler I could borrow this afternoon?"),
    ],
)
def test_a_use_on_another_day_or_a_later_hand_over_waits(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "Tell me when you need it" in frame.decline, frame


def test_a_need_said_for_tomorrow_is_told() -> None:
    frame = _default("I'll need scissors tomorrow")
    assert frame.tasks == [], frame
    assert frame.decline is not None and "Tell me when you need it" in frame.decline, frame


@pytest.mark.parametrize(
    ("words", "today"),
    [
        (["i", "can", "use", "this", "afternoon"], True),
        (["i", "could", "use", "it", "later", "today"], True),
        (["i", "could", "use", "later"], False),
        (["i", "could", "borrow", "this", "afternoon"], False),
        (["i", "could", "use", "tomorrow"], False),
    ],
)
def test_used_later_today(words: list[str], today: bool) -> None:
    assert used_later_today(words) is today
