"""A facility's state asked about, with or without its verb, and a colleague's report beside it
("laminator working today? Bruno said it was jamming yesterday"), is answered in words, never
read as a request nor left as "What should I do?" (blind round 28's class); a request for the
facility's service beside such a question is still done."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "is the laminator working today? Bruno said it was jamming yesterday",
        "is the laminator working? Tove says it's been jamming all week",
        "laminator working today? Bruno said it was jamming yesterday",
        "the laminator working today?",
        "laminator ok today?",
        "laminator still jammed?",
        "is the laminator any better today? Bruno said it was jamming yesterday",
    ],
)
def test_a_facilitys_state_asked_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "laminator" in frame.decline
    assert frame.decline_outcome == "done"


@pytest.mark.parametrize("text", ["laminator free? laminate my file please", "laminate my file?"])
def test_a_request_for_its_service_is_done(text: str) -> None:
    assert [(t.item, t.owner) for t in _frame(text).tasks] == [("file", "ines")]
