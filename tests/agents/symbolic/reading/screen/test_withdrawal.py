"""Withdrawal: "never mind", "forget about ...", "had one already", and the reason told after."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.withdrawal import withdrawn
from reading.screen._judge import Read


@pytest.mark.parametrize("text", ["never mind", "forget about the stapler", "cancel that"])
def test_a_withdrawal_is_found(terms: Terms, message: Read, text: str) -> None:
    msg = message(text)
    found = withdrawn(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.verdict == "withdrawn"
    assert msg.withdrawing


def test_the_reason_told_after_a_withdrawal_is_part_of_it(terms: Terms, message: Read) -> None:
    msg = message("never mind, found the stapler in my drawer")
    first, reason = msg.pieces
    assert withdrawn(terms, msg, first, "lee") is not None
    found = withdrawn(terms, msg, reason, "lee")
    assert found is not None and found.meaning == "the reason the request is withdrawn"


def test_a_request_after_a_withdrawal_is_no_reason(terms: Terms, message: Read) -> None:
    msg = message("never mind, bring me a pen instead")
    first, request = msg.pieces
    assert withdrawn(terms, msg, first, "lee") is not None
    assert withdrawn(terms, msg, request, "lee") is None


def test_a_request_is_no_withdrawal(terms: Terms, message: Read) -> None:
    msg = message("bring me a stapler")
    assert withdrawn(terms, msg, msg.pieces[0], "lee") is None
    assert not msg.withdrawing
