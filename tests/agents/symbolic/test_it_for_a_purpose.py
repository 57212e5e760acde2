"""An "it"/"them" worked on as a file with nothing said that it could be is asked about, also
when a phrase of what or whom it is for follows it ("can u print it off for the induction
table", "print them for the coffee corner session"): a place, a thing or a colleague's thing
named there says what the work is for, never which file "it" is (fix175a class 3,
``reading.antecedent``). Before, the phrase's place was taken for the anchor and the
speaker's own file was printed unasked. A file named after a comma, or before "it", stays."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.antecedent import WHICH_FILE


@pytest.mark.parametrize(
    "text",
    [
        "print it out for the coffee corner session",
        "can u print them off for the kitchenette notice board",
        "can u print it off for the coffee corner induction table",
        "print it for Zhang's induction",
    ],
)
def test_which_file_is_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [], frame
    assert (frame.question or "").startswith(WHICH_FILE), frame


@pytest.mark.parametrize(
    "text",
    [
        "print my report and bring it to me",
        "print it for me, the budget file",
        "print it for the kitchenette, the budget file",
        "print my report for the coffee corner session",
    ],
)
def test_a_file_said_is_printed(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert [(t.kind, t.owner) for t in frame.tasks] == [("print", "lee")], frame
