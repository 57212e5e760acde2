"""Blind round 86's "please courier my signed contract to Channel Nine legal, 12 Harbour
Road" told the operator "courier it to Channel Nine legal": the street was cut, because the
place before the comma ended in a lower-case word, so it did not look like an address or a
proper name. A part after the comma that opens with a house number and a capitalised name is
a street line whatever came before it; ", thanks", "2 copies please" and a clause of its own
are still no part of the place."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers.dataset_offices import default_office_that_sends_out
from helpers.reading import frame_reader


def _default_that_couriers() -> Office:
    """The default office whose printer room couriers a document out."""
    return default_office_that_sends_out(
        "courier", "courier", "courier", "the name and address of the place"
    )


_read = frame_reader(_default_that_couriers, "mao")


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        (
            "please courier my document to Channel Nine legal, 12 Harbour Road",
            "Channel Nine legal, 12 Harbour Road",
        ),
        (
            "courier my document to the Leeds office of Brandt legal, 4 Mill Street, Leeds",
            "the Leeds office of Brandt legal, 4 Mill Street, Leeds",
        ),
        (
            "courier my document to our solicitors, 221 Baker Street",
            "our solicitors, 221 Baker Street",
        ),
        # as before: a proper name before the comma
        ("courier my document to Acme Legal, 12 Mill Road", "Acme Legal, 12 Mill Road"),
        # no street line after the comma: the place stops at it
        ("courier my document to Channel Nine legal, thanks", "Channel Nine legal"),
        (
            "courier my document to the Leeds legal team, then bring me a coffee",
            "the Leeds legal team",
        ),
    ],
)
def test_a_street_line_goes_on_the_destination(text: str, destination: str) -> None:
    frame = _read(text)
    couriers = [t for t in frame.tasks if t.destination is not None]
    assert [t.destination for t in couriers] == [destination], (frame.tasks, frame.question)
