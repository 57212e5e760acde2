""" "send my parcel out on the van run to <a place outside>": the words between "send" and its
"to" (the thing, the particle and how it goes) may run to ten; read only up to seven, the
"to" was missed and the place's first capitalised word asked about as a colleague
("I don't know anyone called 'Swanwick'"), 7 tasks of round 137 lost (``send_off``)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts


def _courier() -> InstructionParser:
    return InstructionParser(
        default_office_that_sends_out("courier", "courier", "courier", "the name and address")
    )


@pytest.mark.parametrize(
    ("text", "where"),
    [
        (
            "send my document out on the afternoon van to Acme Ltd, Mill Road, Leeds",
            "Acme Ltd, Mill Road, Leeds",
        ),
        (
            "send my document out today on the late van to Harbour Marina, berth C14",
            "Harbour Marina, berth C14",
        ),
    ],
)
def test_a_long_way_of_sending_still_reaches_its_place(text: str, where: str) -> None:
    frame = _courier().parse(text, "lin")
    assert frame.question is None, frame
    assert [(t.kind, t.destination) for t in frame.tasks] == [("heat", where)], frame


def test_harbour_posts_it_the_same() -> None:
    frame = InstructionParser(harbour_that_posts()).parse(
        "send my document out on the second post run to Acme Ltd, Mill Road, Leeds", "will"
    )
    assert [(t.kind, t.destination) for t in frame.tasks] == [
        ("heat", "Acme Ltd, Mill Road, Leeds")
    ], frame


def test_a_plain_send_to_a_colleague_is_a_hand_over() -> None:
    frame = _courier().parse("send my document to Zhang", "lin")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "zhang")], frame
