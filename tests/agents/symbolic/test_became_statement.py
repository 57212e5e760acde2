"""A thing said to have become something, with "'s" for "has" and no article ("fridge
light's gone amber again, just fyi", where Amber is also a colleague's name), is a statement
for your information, answered in words (it was met with "What should I do?": blind round 28's
class, an FYI about a light's colour); a colleague gone home is still read as away, and a
request beside the statement is done."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "fridge light's gone amber again, just fyi",
        "fridge light's gone orange again, just fyi",
        "fridge light's gone amber again",
        "the fridge light is on amber again, just so you know",
        "the fridge light has gone orange again, just fyi",
    ],
)
def test_an_fyi_about_a_things_state_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted")


def test_a_colleague_gone_home_is_away() -> None:
    frame = _frame("Bruno's gone home")
    assert frame.decline is not None and "Bruno Keel is away" in frame.decline


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("fridge light's gone amber again, bring me a ruler", ("ruler", None, "ines")),
        ("bring me Tove's tray, Bruno's got one too", ("tray", "tove", "ines")),
    ],
)
def test_a_request_beside_it_is_done(text: str, expected: tuple[str, str | None, str]) -> None:
    assert [(t.item, t.owner, t.recipient) for t in _frame(text).tasks] == [expected]
