""" "have somebody sign my contract" at the start of a message is someone unnamed made to do
the work (``speech._causative``), asked who, as "get someone to sign my contract" is; it had
been read as the question "have somebody signed ...?" and answered "I don't know where your
document is". A participle after the unnamed doer is still the question."""

from __future__ import annotations

import pytest
from _offices import parser

_WHO = "Who should sign your document? Please tell me their name."


@pytest.mark.parametrize(
    "text",
    [
        "have somebody sign my contract",
        "have someone sign my contract please",
        "have somebody sign my contract, then bring me a coffee",
        "get someone to sign my contract please",
    ],
)
def test_the_signer_is_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.decline is None
    assert frame.question == _WHO


def test_neighbour_a_named_signer_signs() -> None:
    frame = parser("default").parse("have Wang sign my contract", "lee")
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("sign", "document", "lee", "wang")
    ]


def test_neighbour_have_anyone_seen_is_a_question() -> None:
    frame = parser("default").parse("have anyone seen my stapler?", "lee")
    assert frame.tasks == [] and frame.question is None
