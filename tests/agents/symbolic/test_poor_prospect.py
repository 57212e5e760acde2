"""A poor prospect of a doing told ("no chance of getting the binders printed before 4", "not
a hope of finishing the slides") is venting: nothing is asked, whatever work its gerund names
(``reading.poor_prospect``). Before, the causative "getting X printed" was left as the
request and the speaker's file was printed. "any chance of ...", "no rush on ..." still ask,
and a request beside the venting still runs."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("default", "lee", "no chance of getting the quarterly binders printed before 4 honestly"),
        ("default", "lee", "no hope of getting my report printed before lunch"),
        ("default", "lee", "little hope of getting my report copied by noon"),
        ("default", "lee", "no way of getting the report printed today tbh"),
        ("default", "lee", "not a hope of finishing the slides today"),
        # Hope works at harbour: the prospect's noun, or a colleague's name said first
        ("harbour", "may", "no hope of getting the quarterly binders printed before 4"),
        ("harbour", "may", "little hope of getting my report copied by noon tbh"),
        ("harbour", "may", "Hope, not a hope of finishing my report today"),
        ("harbour", "may", "Ray, zero chance of me getting my report printed today"),
    ],
)
def test_poor_prospect_moves_nothing(office: str, requester: str, text: str) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == []
    assert frame.question is None  # answered in words, nothing asked back


@pytest.mark.parametrize(
    "text",
    [
        "any chance of getting my report printed",
        "no rush on getting my report printed",
        "no chance of getting my report printed before 4, can you print it now",
    ],
)
def test_a_request_still_asks(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("print", "file", "lee", "lee")]
