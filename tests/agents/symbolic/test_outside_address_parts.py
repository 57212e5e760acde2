"""An outside address said in comma-separated parts to the sentence's end (round 143 class 1):
once a send-out's destination has begun ("to Harlow Council planning department"), parts that
are each a proper name or a numbered line up to the end of the sentence are the address, and a
word in them that names the office's operation, item or colleague ("Water", "Print", "Mill",
"Will") is part of a street's or building's name, never a request nor a party. A clause after
a comma, a colleague said to alone, or a second request after "and" is read as before."""

from __future__ import annotations

import functools

import pytest

from helpers.courier_yard import courier_yard
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.reading import ReadFrame, frame_reader

_yard = frame_reader(courier_yard, "ines")
_harbour = frame_reader(harbour_that_posts, "may")
_default = frame_reader(
    functools.partial(
        default_office_that_sends_out, "courier", "send by courier", "courier", "the address"
    ),
    "chen",
)

_HARLOW = "Harlow Council planning department, Civic Centre, Water Gardens, Harlow"


@pytest.mark.parametrize(
    ("read", "text", "place"),
    [
        (_yard, f"Courier the signed contract to {_HARLOW}.", _HARLOW),
        (_yard, f"courier my contract to {_HARLOW}.", _HARLOW),
        (
            _yard,
            "dispatch my letter to Acme Ltd, Mill Road, Cambridge",
            "Acme Ltd, Mill Road, Cambridge",
        ),
        (
            _yard,
            "courier my invoice to the county office, Print House, Will Street, York",
            "the county office, Print House, Will Street, York",
        ),
        (
            _yard,
            "could you courier my form to Bayside Clinic, Water Lane, Leeds please",
            "Bayside Clinic, Water Lane, Leeds",
        ),
        (
            _harbour,
            "post my letter to the county office, Printers Yard, Water Street, York",
            "the county office, Printers Yard, Water Street, York",
        ),
        (
            _harbour,
            "post my letter to the tax office, Will House, Scan Lane, Hull",
            "the tax office, Will House, Scan Lane, Hull",
        ),
        (_harbour, f"post my letter to {_HARLOW}.", _HARLOW),
        (
            _default,
            "courier my contract to Bayside Clinic, 4 Coffee Lane, Leeds",
            "Bayside Clinic, 4 Coffee Lane, Leeds",
        ),
        (
            _default,
            "courier my contract to the planning office, Coffee House, Print Street, Leeds",
            "the planning office, Coffee House, Print Street, Leeds",
        ),
    ],
)
def test_the_address_parts_are_the_destination(read: ReadFrame, text: str, place: str) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.destination for t in frame.tasks] == [place], frame.tasks


# -- must not change ---------------------------------------------------------------------


def test_a_second_request_after_and_is_made() -> None:
    frame = _default("courier my contract to Bayside Clinic and bring me a coffee")
    assert [(t.destination, t.item) for t in frame.tasks] == [
        ("Bayside Clinic", "document"),
        (None, "coffee"),
    ]


@pytest.mark.parametrize("read", [_harbour, _default])
def test_an_unoffered_second_request_is_still_declined(read: ReadFrame) -> None:
    verb = "post" if read is _harbour else "courier"
    frame = read(f"{verb} my letter and water the plants")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, I can't water"), frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "courier my contract to Acme Ltd, Will",  # said to Will
        "courier my contract to Acme Ltd, it has to go today",  # a clause of its own
    ],
)
def test_a_part_that_is_no_address_ends_the_destination(text: str) -> None:
    frame = _yard(text)
    assert [t.destination for t in frame.tasks] == ["Acme Ltd"], frame
