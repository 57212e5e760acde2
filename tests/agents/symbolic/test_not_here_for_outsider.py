"""A thing nobody here has, asked for someone outside the office, is said to be unknown here
("grab a box of aspirin out of the cabinet for the customer at the till" was met with "Shall I
bring it to you instead?", an offer of nothing: blind round 28's class); a thing the office has,
or one said before, for an outsider is still asked about, and nothing moves either way."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        (
            "grab a box of aspirin out of the cabinet for the customer at the till",
            "box of aspirin",
        ),
        ("could you get some plasters for the delivery guy", "plasters"),
        ("bring a mug of cocoa to the visitor", "mug of cocoa"),
    ],
)
def test_a_thing_not_here_for_an_outsider_is_declined(text: str, thing: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"any {thing} in this office" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "bring a ruler to the customer at the till",
        "take it to the visitor",
        "bring a few for the visitor",
    ],
)
def test_the_offices_thing_for_an_outsider_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and "Shall I bring it to you instead" in frame.question
