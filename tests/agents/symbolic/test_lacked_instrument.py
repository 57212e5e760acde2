"""A lack of an instrument is a need of it: "have nothing to measure it with", "got nothing
to cut with", "nothing to measure it with", "no way to measure it" ask for the office's item
declared for that use, brought to the speaker (round 166, class 2;
``reading.lacked_purpose``; the plain "has nothing to write with" is
test_lacked_purpose.py's). A lack that names no use of a thing ("nothing to do", "nothing
to report", "there's no way to ...") asks for nothing."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_kit = frame_reader(kit_room, "ana")


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue
        "I'm pinning up a hem and have nothing to measure it with",
        # variants: clipped subject, an object noun, no "with", "I've got"
        "got nothing to measure with",
        "nothing to measure it with",
        "no way to measure it",
        "I have nothing to measure the costume with",
        "I've got nothing to measure this with, sorry",
    ],
)
def test_a_lacked_instrument_is_brought(text: str) -> None:
    frame = _kit(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "tape_measure", None, "ana")
    ], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "item"),
    [
        ("default", "lee", "I'm fixing a hem and have nothing to cut it with", "scissors"),
        ("default", "lee", "got nothing to write with", "pen"),
        ("default", "lee", "I have no way to cut the tape", "scissors"),
        ("harbour", "may", "I'm marking out a poster and have nothing to measure it with", "ruler"),
        ("harbour", "may", "no way to calculate it", "calculator"),
    ],
)
def test_the_same_on_the_dataset_offices(office: str, requester: str, text: str, item: str) -> None:
    assert tasks_of(office, text, requester) == [("transfer", item, None, requester)]


@pytest.mark.parametrize(
    "text",
    [
        "I have nothing to do",  # no use of a thing
        "nothing to report",  # no instrument said
        "no way to fix it",  # no item of the office is for fixing
    ],
)
def test_a_lack_of_no_instrument_moves_nothing(text: str) -> None:
    assert _kit(text).tasks == []


def test_a_lack_that_is_nobodys_moves_nothing() -> None:
    # "there's no way ...": no one's lack, though harbour's charger is for charging
    assert tasks_of("harbour", "there's no way to charge it here", "may") == []
