"""A facility said inside the purpose of a thing asked for ("a multimeter to check the
compressor's wiring") is where the thing is used: no service of the facility is asked of the
thing (it had been read as filling the multimeter at the compressor, and asked "Whose
multimeter?"). The thing taken to the facility, or a service asked by its verb, keeps the
service. On a small office (helpers.dive_van) and the default office."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.dive_van import dive_van
from helpers.reading import frame_reader

_van = frame_reader(dive_van, "lee")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a multimeter to check the compressor's sensor wiring.", "multimeter"),
        ("I need a multimeter to check the compressor wiring", "multimeter"),
        ("can I borrow a multimeter to test the compressor's fuse", "multimeter"),
        ("need a probe thermometer to check the workshop bench", "probe_thermometer"),
    ],
)
def test_a_facility_in_the_purpose_asks_no_service(text: str, item: str) -> None:
    frame = _van(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "can you take my cylinder to the compressor",  # taken there: the fill
        "bring my tank to the compressor to be filled",
        "could you fill my cylinder at the compressor",
    ],
)
def test_a_thing_taken_to_the_facility_keeps_its_service(text: str) -> None:
    frame = _van(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.operation, t.item) for t in frame.tasks] == [("heat", "fill", "cylinder")]


def test_the_default_offices_microwave_said_in_a_purpose_heats_nothing() -> None:
    frame = _default("I need the scissors to open the microwave's new box")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "scissors")]
