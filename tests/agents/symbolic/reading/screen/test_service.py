"""Unsupported service: declined, never swapped for something else."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.service import unsupported
from assistantx.agents.symbolic.reading.screen.terms import Terms

Read = Callable[[str], Message]


def test_a_service_the_office_does_not_offer_is_declined(terms: Terms, message: Read) -> None:
    msg = message("scan my contract")
    found = unsupported(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.verdict == "unsupported"
    assert found.message.startswith("Sorry, I can't scan: nothing in this office offers that")


def test_a_product_the_office_does_not_make_is_declined(terms: Terms, message: Read) -> None:
    msg = message("bring me a cup of tea")
    found = unsupported(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.meaning == "not offered here: tea"


def test_the_speakers_own_doing_beside_a_request_is_context(terms: Terms, message: Read) -> None:
    msg = message("I need to scan the bill. Could you bring me a pen?")
    found = unsupported(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.verdict == "statement"


def test_an_offered_service_passes(terms: Terms, message: Read) -> None:
    msg = message("print my file")
    assert unsupported(terms, msg, msg.pieces[0], "lee") is None
