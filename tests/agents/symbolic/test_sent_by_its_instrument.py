"""A service that sends an item out of the office, named by its instrument ("by the tube",
"on the tube", "via pneumatic tube") with a destination outside ("to microbiology", "to the
lab"), sends it there: "send my swab to microbiology by the tube" asked whom to give the
sample to ("to microbiology" was read as a purpose, "to <verb>", and the service with it),
and "... off to the lab on the tube" lost the lab. Nothing sent out is handed to a colleague
named in the same message; a plain hand-over to a colleague is read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tube_ward import tube_ward

_frame = frame_reader(tube_ward, "kim")


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("Send my swab to microbiology by the tube please", "microbiology"),
        ("send my sample to haematology by tube", "haematology"),
        ("send my specimen to pathology via pneumatic tube", "pathology"),
        ("send my sample to the lab on the pneumatic tube", "the lab"),
        ("get my sample off to the lab on the tube", "the lab"),
        ("send my sample to the lab via the tube", "the lab"),
        ("tube my sample to microbiology", "microbiology"),
    ],
)
def test_sent_out_by_its_instrument_to_a_place_outside(text: str, destination: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.item, t.operation, t.destination) for t in frame.tasks] == [
        ("sample", "tube", destination)
    ], frame


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("Take my form to Dr Ames and get my sample off to the lab on the tube", "the lab"),
        ("Take my form to Dr Ames and send my sample to microbiology by the tube", "microbiology"),
    ],
)
def test_the_sample_sent_out_is_never_handed_to_the_colleague(text: str, destination: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    handed = [(t.item, t.recipient) for t in frame.tasks if t.operation is None]
    sent = [(t.item, t.destination) for t in frame.tasks if t.operation == "tube"]
    assert handed == [("form", "ames")] and sent == [("sample", destination)], frame


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("send my sample to Dr Ames", "transfer", "ames"),
        ("Take my form to Dr Ames", "transfer", "ames"),
        ("give my form to Ravi to sign", "sign", "kim"),
    ],
)
def test_a_colleague_still_gets_what_is_handed_to_them(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient, t.destination) for t in frame.tasks] == [
        (kind, recipient, None)
    ], frame
