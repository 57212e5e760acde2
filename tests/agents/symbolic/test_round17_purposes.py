"""Blind round 17's purpose class, on a school arts block no sentence was written for
(``helpers.arts_block``; the round's office and sentences were never read): "for PE cover",
"for Year 9 sports day", "for the Y9 trip" say what the thing is for, not whom; a name of
nobody in the office after "for" is still asked about, and a colleague's name still gets it."""

from __future__ import annotations

import pytest

from helpers.arts_block import arts_block
from helpers.reading import frame_reader

_frame = frame_reader(arts_block, "marta")


@pytest.mark.parametrize(
    "text",
    [
        "grab me a stopwatch for PE cover please",
        "grab me a stopwatch for Year 9 sports day",
        "grab me a stopwatch for period 3 please",
        "grab me a stopwatch for the Y9 trip please",
        "can you get a stopwatch for Drama club",
    ],
)
def test_a_purpose_after_for_is_no_person(text: str) -> None:
    frame = _frame(text, "marta")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stopwatch", "marta")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "grab me a stopwatch for Kowalski please",
        "grab a stopwatch for Kowalski tomorrow",
        "grab a stopwatch for Kowalski this afternoon",
        "grab a stopwatch for Kowalski next week",
    ],
)
def test_an_unknown_name_after_for_is_still_asked_about(text: str) -> None:
    frame = _frame(text, "marta")
    assert frame.tasks == [] and frame.question is not None and "Kowalski" in frame.question


@pytest.mark.parametrize(
    "text", ["bring a stopwatch for Colm please", "bring a stopwatch for Colm tomorrow"]
)
def test_a_colleague_after_for_still_gets_it(text: str) -> None:
    assert [(t.item, t.recipient) for t in _frame(text, "marta").tasks] == [("stopwatch", "colm")]


def test_a_question_with_a_purpose_moves_nothing() -> None:
    assert _frame("did you grab a stopwatch for PE cover?", "marta").tasks == []
