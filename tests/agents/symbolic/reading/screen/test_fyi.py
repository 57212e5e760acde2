"""A message that says it only informs is noted; a request beside the tag is still done."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "liu")


@pytest.mark.parametrize(
    "text",
    [
        "fridge temp light is on amber again, just so you know",  # blind round 28's case
        "fyi the printer is making that clicking noise again",
        "the microwave smells of fish again. heads up",
        "just letting you know the fridge door won't shut properly",
    ],
)
def test_told_for_information_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "I did nothing" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "fyi I'm in at 9, can you print my file?",
        "just so you know I need Zhang's stapler, could you bring it",
    ],
)
def test_a_request_beside_the_tag_is_done(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks, frame
