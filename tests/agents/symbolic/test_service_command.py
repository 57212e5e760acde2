"""A service asked for in the imperative is a request whatever its object is
(``reading/service_command``): "fax the booking confirmation to the travel agent", where the
office has no fax, is declined as "fax the contract to the lawyer" is, never noted as a
statement because "the *booking* confirmation" looks like a clause. The service word as a
noun ("the fax came through"), in the plural ("faxes are ...") or in the past ("I faxed it")
is still told."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.service_command import service_command


def _decline(office: str, text: str, who: str) -> str | None:
    frame = parser(office).parse(text, who)
    assert not frame.tasks and frame.question is None
    return frame.decline


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("fax the contract to the lawyer", "fax"),  # already declined: the reference
        ("fax the booking confirmation to the travel agent", "fax"),
        ("fax the meeting notes to the travel agent", "fax"),
        ("fax the quarterly figures to the accountant", "fax"),
        ("please fax my travel plans to the agency", "fax"),
        ("laminate the meeting notes", "laminate"),
        ("courier the signed contract to the depot", "courier"),
    ],
)
def test_an_unoffered_service_in_the_imperative_is_declined_on_the_default_office(
    text: str, verb: str
) -> None:
    decline = _decline("default", text, "lin")
    assert decline is not None and f"can't {verb}" in decline


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("fax the booking confirmation to the travel agent", "fax"),
        ("copy the meeting notes for the harbour master", "copy"),
        ("copy the opening hours for the visitors", "copy"),
        ("fax my sailing schedule to the marina", "fax"),
    ],
)
def test_an_unoffered_service_in_the_imperative_is_declined_on_harbour(
    text: str, verb: str
) -> None:
    decline = _decline("harbour", text, "may")
    assert decline is not None and f"can't {verb}" in decline


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lin", "faxes are so old-fashioned"),
        ("default", "lin", "the fax came through"),
        ("default", "lin", "I faxed it yesterday"),
        ("harbour", "may", "the courier came through at noon"),
        ("harbour", "may", "I copied the meeting notes yesterday"),
    ],
)
def test_the_service_word_told_is_still_a_statement(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert not frame.tasks and frame.question is None
    assert frame.decline is None or "can't" not in frame.decline


@pytest.mark.parametrize(
    ("words", "command"),
    [
        (["fax", "the", "booking", "confirmation"], True),
        (["just", "laminate", "these"], True),
        (["shred", "my", "old", "drafts"], True),
        (["faxes", "are", "old"], False),
        (["the", "fax", "came", "through"], False),
        (["faxed", "the", "contract"], False),
        (["fax", "machine", "is", "down"], False),  # a noun heading the subject
    ],
)
def test_service_command_reads_the_verb_and_its_objects_opener(
    words: list[str], command: bool
) -> None:
    assert service_command(words) is command
