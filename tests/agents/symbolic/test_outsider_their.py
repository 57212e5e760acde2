"""A possessive pronoun whose antecedent is an outsider said by what they are ("the client",
"the auditors", "the visitors") in the reason after a request ("please photocopy my contract,
the client wants a copy for their files") is theirs: it names no colleague, so nobody is asked
about (``reading._parties.owner_of``). With no outsider before it, or an outsider with no
request before, whom it means is still asked."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "please photocopy my contract, the client wants a copy for their files",
        "copy my contract, the visitors want one for their files",
        "copy my contract because the client would like one for their files",
        "can you photocopy my contract? the auditor needs a copy for his files",
    ],
)
def test_the_outsiders_possessive_asks_nobody(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("copy", "document", "lee", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        # must not change: nobody said before "their"/"his", or no request before the outsider
        "copy my contract for their files",
        "the client wants his stapler back",
        "bring me his stapler",
    ],
)
def test_with_no_outsider_in_a_reason_whom_is_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith("Who do you mean by"), frame.question
