"""A report of what happened, opened by the speaker's own return said with no subject ("Just
back from site.", "Back off the hill.") and ending with the speaker's own plan ("I'll order
a new one Monday."), asks nothing: answered in words, nothing moves. A request beside it
("can you get me a new one?", "could you find me one?") is still a request."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_frame = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Just back off the hill. Snapped my pen on the stairs. I'll sort a new one tomorrow.",
        "Just back from site. Cracked my cup on a beam. I'll order a new one Monday.",
        "Finally back off the road. Lost my stapler at the second stop. I'll sort one tomorrow.",
        "Back off the ward. Broke my scissors on a box. I'll get new ones later.",
        "Only just back from the depot. Dropped my cup in the yard. I'll grab another later.",
    ],
)
def test_a_report_and_the_speakers_own_plan_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    "text",
    [
        "Just back from site. Snapped my pen. can you get me a new one?",
        "Just back off the hill. I'll need a new pen, could you find me one?",
        "Back off the road. Lost my stapler, please bring me a stapler",
    ],
)
def test_a_request_beside_the_report_is_still_a_request(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [t.kind for t in frame.tasks] == ["transfer"], frame
    assert frame.tasks[0].item == "stapler" or frame.tasks[0].item == "pen", frame
