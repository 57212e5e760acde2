"""A wish about what a person would do for the requester ("it would be great if Hal could
sign my form") is a request naming who does the work; the same words told as done ("Hal
signed my form yesterday") are a statement, and nothing moves (issue 23)."""

from __future__ import annotations

import pytest
from _offices import parser as office_parser

from assistantx.agents.symbolic import InstructionParser


@pytest.mark.parametrize(
    "text",
    [
        "it would be great if Hal could sign my form",
        "I'd love it if Hal signed my form today",
        "would be nice if Hal would sign my form",
        "I wish Hal would sign my form",
    ],
)
def test_a_wish_that_a_person_would_sign_is_a_request_for_them_to(
    clinic_parser: InstructionParser, text: str
) -> None:
    frame = clinic_parser.parse(text, "dawn")
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("sign", "dawn", "hal")]


def test_the_default_office_too() -> None:
    frame = office_parser("default").parse(
        "it would be great if Dr Zhang could sign my contract", "lee"
    )
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "zhang")]


@pytest.mark.parametrize("text", ["Hal signed my form yesterday", "Hal signs forms on Fridays"])
def test_the_same_work_told_as_done_moves_nothing(
    clinic_parser: InstructionParser, text: str
) -> None:
    frame = clinic_parser.parse(text, "dawn")
    assert frame.tasks == [] and frame.decline is not None
