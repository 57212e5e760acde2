"""A paper named by the possessive of an outsider the speaker serves, said with an article or a
demonstrative ("the customer's V5C", "this patient's form"), is in the speaker's hands: a service
asked on it runs on the requester's own paper, as "my client's" already did (``readings``'
unknown-name check). The outsiders are words of English for what a person is to the speaker
(``outsider_nouns``: customer, client, patient, visitor, supplier), never people of the
office; a possessive that names a colleague keeps its meaning, and an outsider's paper to be
fetched ("bring me the client's contract") is still asked about."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

Row = tuple[str, str | None, str | None, str]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("photocopy the client's contract for me", [("copy", "document", "zhang", "zhang")]),
        ("can you copy the patient's form", [("copy", "document", "zhang", "zhang")]),
        (
            "could you photocopy this customer's invoice please",
            [("copy", "document", "zhang", "zhang")],
        ),
        ("photocopy the visitor's form for Wang", [("copy", "document", "zhang", "wang")]),
        ("print the supplier's file for me", [("print", "file", "zhang", "zhang")]),
    ],
)
def test_a_service_on_an_outsiders_paper_is_on_the_requesters_default(
    text: str, expected: list[Row]
) -> None:
    assert tasks_of("default", text, "zhang") == expected


@pytest.mark.parametrize(
    "text",
    [
        "Scan the customer's form to PDF for me",
        "could you scan the client's contract for me",
        "can you scan the patient's letter",
    ],
)
def test_a_service_on_an_outsiders_paper_is_on_the_requesters_harbour(text: str) -> None:
    assert tasks_of("harbour", text, "may") == [("copy", "document", "may", "may")]


def test_a_colleagues_possessive_keeps_its_meaning() -> None:
    assert tasks_of("harbour", "scan Mark's letter for me", "may") == [
        ("copy", "document", "mark", "may")
    ]
    assert tasks_of("default", "photocopy Wang's contract for me", "zhang") == [
        ("copy", "document", "wang", "zhang")
    ]


@pytest.mark.parametrize("text", ["bring me the client's contract", "bring me a customer's form"])
def test_an_outsiders_paper_to_be_fetched_is_still_asked_about(text: str) -> None:
    frame = parser("default").parse(text, "zhang")
    assert frame.tasks == [] and frame.question, frame
