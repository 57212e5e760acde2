"""Negation: "don't bring me ...", "no need to ...", "don't bother fetching ..."."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.screen.negation import negated
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms

Read = Callable[[str], Message]


@pytest.mark.parametrize(
    "text",
    [
        "don't bring me a stapler",
        "no need to print my file",
        "please don't bother bringing me a ruler",
        "do not ever print my file",
    ],
)
def test_a_negated_request_is_found(terms: Terms, message: Read, text: str) -> None:
    msg = message(text)
    found = negated(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.verdict == "negated"


@pytest.mark.parametrize(
    "text",
    [
        "I can't find my stapler",  # the negation is not on the request's verb
        "bring me a stapler",
        "don't forget to bring me a pen",  # still asks for it
    ],
)
def test_what_is_not_a_negated_request(terms: Terms, message: Read, text: str) -> None:
    msg = message(text)
    assert negated(terms, msg, msg.pieces[0], "lee") is None
