"""When a service comes, told as its word's clause ("Courier's due at 3", "courier's coming at
3", "post's going at 4", "courier due at 3"), is a deadline: context for the request beside
it, never the service asked for (fix154a class 1: a museum's "Can you get my loan agreement
stamped ...? Courier's due at 3." was asked which item to shred or courier or photograph).
"courier my contract at 3" still asks for the courier."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import harbour_office
from helpers.loans_desk import loans_desk
from helpers.notary_office import notary_office
from helpers.reading import ReadFrame, frame_reader

_loans = frame_reader(loans_desk, "gwen")
_notary = frame_reader(notary_office, "ruth")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    "text",
    ["Courier's due at 3.", "courier's coming at 3", "courier due at 3", "courier coming at 3"],
)
def test_a_service_timing_alone_asks_for_nothing(text: str) -> None:
    for read in (_loans, _notary):
        frame = read(text)
        assert frame.tasks == [] and frame.question is None, frame


def test_the_post_going_at_a_time_is_a_statement_in_harbour() -> None:
    frame = _harbour("post's going at 4")
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Can you get my loan agreement stamped with the accession stamp? Courier's due at 3.",
            ("seal", "paper", "gwen", None),
        ),
        (
            "Courier's due at 3, can you photograph my loan agreement?",
            ("copy", "paper", "gwen", None),
        ),
        (
            "courier's coming at 3 - get my form signed by Marek pls",
            ("sign", "paper", "gwen", "marek"),
        ),
        (
            "can you get my form signed by Marek? Courier's coming at 3.",
            ("sign", "paper", "gwen", "marek"),
        ),
    ],
)
def test_the_request_beside_a_service_timing_is_done_in_a_museum(
    text: str, task: tuple[str, str, str, str | None]
) -> None:
    frame = _loans(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks] == [task]


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_notary, "Courier's due at 3, can you photocopy my letter?", ("copy", "document", "ruth")),
        (_notary, "post's going at 4, can you photocopy my contract", ("copy", "document", "ruth")),
        (_harbour, "post's going at 4, can you print my file", ("print", "file", "rose")),
        (
            _harbour,
            "can you get my document signed by Grace? post's going at 4",
            ("sign", "document", "rose"),
        ),
    ],
)
def test_a_service_timing_before_or_after_a_request_leaves_it_alone(
    read: ReadFrame, text: str, task: tuple[str, str, str]
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task]


@pytest.mark.parametrize(
    "text", ["courier my contract at 3", "courier my loan agreement, it's due at 3"]
)
def test_the_service_asked_for_at_a_time_is_still_asked(text: str) -> None:
    frame = _loans(text)
    assert frame.tasks == [] and frame.question is not None and "courier" in frame.question, frame
