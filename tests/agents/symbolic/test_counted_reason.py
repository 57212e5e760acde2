"""A count of papers in a reason is no document to act on (blind round 109's class; its own
sentences were never read): "need paper pls, like 20 contracts to print today" asks for paper
only; the count after the comma ("like 20 ...", "got 30 ...", "about a dozen ...") says why.
A second part told as a request ("and print my 20 letters") is read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lee = frame_reader(default_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need paper pls, like 20 contracts to print today", "paper"),
        ("a pen please, got 30 invoices to sign", "pen"),
        ("need a stapler, about a dozen reports to bind", "stapler"),
    ],
)
def test_a_count_after_the_request_is_its_reason(text: str, item: str) -> None:
    frame = _lee(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "lee")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("need tape pls, like 20 parcels going out today", "transfer", "tape"),
        ("a notepad please, like 30 invoices to print today", "produce", "notepad"),
    ],
)
def test_the_same_in_harbour(text: str, kind: str, item: str) -> None:
    frame = _may(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "may")], frame


@pytest.mark.parametrize(
    ("read", "text", "who", "item"),
    [
        (_lee, "need paper, and print my 20 letters", "lee", "paper"),
        (_may, "need tape, print my 20 letters", "may", "tape"),
    ],
)
def test_a_second_request_is_still_two_parts(
    read: ReadFrame, text: str, who: str, item: str
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", item, who),
        ("print", "file", who),
    ], frame
