"""A fact told after a request about the one the request takes a thing to ("take my calculator
back to Ana, she lent me hers and needs it") is the back-story of the errand, not "what was
asked for is had already" (blind round 55's class; its office and sentences were never read):
the request stands. Told after a request that brings the speaker a thing, the same fact still
withdraws it ("bring me a ruler - oh wait, Sam lent me his")."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        (
            "please drop my clippers back with Sam, he lent me his and needs a pair",
            "clippers",
            "sam",
        ),
        (
            "take my calculator back to Ana, she lent me hers and needs it for the audit",
            "calculator",
            "ana",
        ),
        ("return my ruler to Sam, Sam lent me his", "ruler", "sam"),
        (
            "please give my ruler back to Bill. he lent me his yesterday and needs it",
            "ruler",
            "bill",
        ),
        ("can you take my mask over to Ana? she lent me hers this morning", "mask", "ana"),
    ],
)
def test_a_fact_of_the_recipient_is_the_back_story(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "gwen", recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a ruler - oh wait, Sam lent me his",
        "bring me Sam's ruler - oh wait, he lent me his",
        "could you get me a calculator? oh actually Ana lent me hers",
    ],
)
def test_had_already_after_a_request_for_the_speaker_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline
