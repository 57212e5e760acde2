"""Negation: "don't bring me ...", "no need to ...", "don't bother fetching ..."."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.negation import negated
from reading.screen._judge import Judge


@pytest.mark.parametrize(
    "text",
    [
        "don't bring me a stapler",
        "no need to print my file",
        "please don't bother bringing me a ruler",
        "do not ever print my file",
    ],
)
def test_a_negated_request_is_found(judged: Judge, text: str) -> None:
    found = judged(negated, text, "lee")
    assert found is not None and found.verdict == "negated"


@pytest.mark.parametrize(
    "text",
    [
        "I can't find my stapler",  # the negation is not on the request's verb
        "bring me a stapler",
        "don't forget to bring me a pen",  # still asks for it
    ],
)
def test_what_is_not_a_negated_request(judged: Judge, text: str) -> None:
    assert judged(negated, text, "lee") is None
