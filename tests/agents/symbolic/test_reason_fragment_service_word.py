"""A verbless fragment giving the reason for a request, whose first word is also a service
nobody here offers ("need a charging cable, phone at 2%", "..., phone nearly dead"): a thing
and its state, context (blind round 55's class; its office and sentences were never read).
The request stands; the service asked for by its verb is still declined."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")


@pytest.mark.parametrize(
    "text",
    [
        "need a charging cable, phone at 2%",
        "need a charging cable, phone dead",
        "can you get me a cable? phone at 2%",
        "grab me a cable - phone nearly dead",
        "need a cable, phone out of charge",
        "bring me a cable, phone almost flat",
    ],
)
def test_the_request_stands(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "cable", "gwen")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "phone Ana for me",
        "bring me a cable, phone the lab now",
        "bring me a cable, phone Ana too",
        "bring me a cable, phone later",
        "phone at 2%",
    ],
)
def test_the_service_asked_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is not None and "can't phone" in frame.decline, frame
