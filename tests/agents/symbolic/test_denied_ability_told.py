""" "can barely see a thing", "could hardly hear you": a modal of ability with its subject
dropped and an adverb that nearly denies the verb tells the speaker's state ("Noted"), never
a request nobody made (round 238's default-office case "the sun is glaring on my screen
today, can barely see a thing" asked "what should I do?"). A request beside it is read."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.modal_told import denied_ability
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "sun")


@pytest.mark.parametrize(
    "text",
    [
        "the sun is glaring on my screen today, can barely see a thing",
        "it's freezing in here, can hardly feel my fingers",
        "could barely hear a word in that meeting",
    ],
)
def test_the_speakers_state_is_told(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted"), frame


def test_a_request_beside_it_is_read() -> None:
    frame = _frame("could hardly hear you, can you bring me the book")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("book", "sun")], frame


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        ("can barely see a thing", True),
        ("couldnt hardly move", True),
        ("can you bring me a stapler", False),
        ("can not find it", False),  # either reading: left to the other rules
        ("can barely", False),  # nothing after the adverb
    ],
)
def test_denied_ability(words: str, expected: bool) -> None:
    assert denied_ability(words.split()) is expected
