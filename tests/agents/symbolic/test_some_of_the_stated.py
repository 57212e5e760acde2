"""Blind rounds 40 to 42 (fixer B, class 3), on sentences of our own against the default office:
"some" after a statement points at the thing the statement is about, not at a paper named in
its purpose phrase with describing words ("out of paper for the grant report, get me some":
the paper, a supply, to the requester; it asked whose document). The purpose's item after "for
the" and up to two describing words modifies the thing; "for my report" read so before."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "I've run out of paper for the grant report, could you get me some?",
        "We've run out of paper for the annual sales report. Can you get me some?",
        "I've got no paper left for the big report, could you grab me some please",
        "We're out of paper for Zhang's quarterly report, could you get me some?",
        # near-misses, read as before
        "I've run out of paper for my report, could you get me some?",
        "I've run out of paper, could you get me some?",
    ],
)
def test_some_is_the_thing_the_statement_is_about(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", "paper", None, "lee")]
