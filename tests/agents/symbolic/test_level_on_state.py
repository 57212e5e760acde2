"""A thing's level said with "on" after a need ("need a charger, phone on 3%", "..., phone on
5 percent", "..., battery on 1%") is the reason for the request, like "phone at 2%": the "on"
of a level is no adverb ("carry on") that the state's reading skips, so "phone" stays the
thing of a state told, never the phoning service asked for. A "phone" with someone or a day
after it is still the service, declined."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "bill")
_DEFAULT = frame_reader(default_office, "wu")


@pytest.mark.parametrize(
    "text",
    [
        "need a charger, phone on 3%",
        "could you bring me a charger? phone on 5 percent",
        "need a charger - phone on like 3%",
        "need a charger, my phone's on 2 percent",
        "need a charger, phone dying",
        "need a charger, battery on 1%",
    ],
)
def test_harbour_the_level_is_the_reason(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.decline is None, frame
    got = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "charger", "bill")], frame


@pytest.mark.parametrize(
    "text",
    [
        "need a data cable, phone on 3%",
        "grab me a cable, phone on about 4 percent",
        "need a cable. phone on 3%",
        "need a cable, laptop at 5%",
    ],
)
def test_default_office_the_level_is_the_reason(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.decline is None, frame
    got = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "data_cable", "wu")], frame


@pytest.mark.parametrize(
    "text",
    [
        "phone on 3%",  # no request beside it: the service is what was said
        "need a charger, phone on Monday",  # a day, no level: phoning asked
        "bring me a charger, phone Ray on 5",  # someone to call
    ],
)
def test_harbour_phoning_is_still_declined(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.decline is not None and "can't phone" in frame.decline, frame
