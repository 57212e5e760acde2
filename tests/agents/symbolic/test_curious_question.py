"""A question said to be asked out of curiosity is answered in words, with nothing offered
("who's got a ruler? just curious, not urgent" was met with "What should I do?": blind round
28's class); an unhurried aside beside a question leaves its offer, and beside a request the
request is done."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    ("text", "answer"),
    [
        ("who's got a ruler? just curious, not urgent", "Bruno Keel has a ruler"),
        ("who's got a ruler? I'm just curious", "Bruno Keel has a ruler"),
        ("who has a tray? just curious", "Bruno Keel and Tove Lind have a tray"),
        ("does anyone have a ruler? just wondering, no rush", "Bruno Keel has a ruler"),
        ("who has a tray? purely out of curiosity", "Bruno Keel and Tove Lind have a tray"),
    ],
)
def test_a_curious_question_is_answered_in_words(text: str, answer: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and answer in frame.decline
    assert "Shall I" not in frame.decline


@pytest.mark.parametrize("text", ["who's got a ruler? not urgent", "who's got a ruler?"])
def test_a_plain_question_still_offers(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and "Shall I bring you one?" in frame.question


@pytest.mark.parametrize(
    "text", ["bring me a ruler, no rush", "who's got a ruler? bring it to me, no rush"]
)
def test_a_request_beside_an_aside_is_done(text: str) -> None:
    assert [(t.kind, t.item, t.recipient) for t in _frame(text).tasks] == [
        ("transfer", "ruler", "ines")
    ]
