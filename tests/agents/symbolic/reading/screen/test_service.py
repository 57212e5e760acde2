"""Unsupported service: declined, never swapped for something else."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.service import unsupported
from reading.screen._judge import Judge


def test_a_service_the_office_does_not_offer_is_declined(judged: Judge) -> None:
    found = judged(unsupported, "scan my contract", "lee")
    assert found is not None and found.verdict == "unsupported"
    assert found.message.startswith("Sorry, I can't scan: nothing in this office offers that")


def test_a_product_the_office_does_not_make_is_declined(judged: Judge) -> None:
    found = judged(unsupported, "bring me a cup of tea", "lee")
    assert found is not None and found.meaning == "not offered here: tea"


def test_the_speakers_own_doing_beside_a_request_is_context(judged: Judge) -> None:
    found = judged(unsupported, "I need to scan the bill. Could you bring me a pen?", "lee")
    assert found is not None and found.verdict == "statement"


def test_an_offered_service_passes(judged: Judge) -> None:
    assert judged(unsupported, "print my file", "lee") is None
