""" "that"/"those" said alone as a work's object with nothing in the message they could be
("print that out for me") point back as "it" does: which file is asked, never the speaker's
own guessed (fix175a asked so for "it"; ``reading.antecedent``). A far demonstrative before
its noun, one after a thing said, and "this" at hand keep their readings."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("print that out for me", "that"),
        ("can you print that", "that"),
        ("could you print those off for me please", "those"),
        ("print that one for Wang", "that"),
    ],
)
def test_that_with_nothing_said_asks_which_file(text: str, said: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [], frame
    assert frame.question is not None and f"'{said}'" in frame.question


def test_the_answer_is_what_that_means() -> None:
    frame = parser("default").parse_with_answers("print that out for me", "lee", ["Wang's"])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "wang", "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a noun after it, a thing said before it, "this" at hand
        "print that report for me",
        "my report is done, print that out for me",
        "print this for me",
    ],
)
def test_that_with_something_said_reads_as_before(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("print", "file", "lee", "lee")]
