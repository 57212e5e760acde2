"""The destination stage of a service that sends outside: the requester's own words after the
service's verb and "to", never a guess."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.destination import destination

FAX = ("fax", "faxes", "faxed", "faxing")


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("fax my form to the county tax office", "the county tax office"),
        ("Fax it to 020 7946 0000 please", "020 7946 0000"),
        ("send this to Lee and fax my form to the bank. Thanks", "the bank"),
        ("faxed to Müller & Søn GmbH, asap", "Müller & Søn GmbH"),
    ],
)
def test_the_words_after_the_verb_and_to(text: str, where: str) -> None:
    assert destination(text, FAX) == where


@pytest.mark.parametrize(
    "text",
    ["fax my form", "please fax my form, it has to go today", "take it to Lee", "fax my form to"],
)
def test_no_destination_is_none(text: str) -> None:
    assert destination(text, FAX) is None
