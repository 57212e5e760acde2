"""The purpose's own object said as a noun phrase of several nouns ("to measure voltage on
the lift control panel", "to charge my phone battery") says where or on what the thing found
by the purpose is used: the whole phrase is the purpose's (``screen.rewrites.purposes``), and
none of its nouns is glued to the thing ("a multimeter control panel", asked about as
unknown). On a small office (helpers.dive_van) and the default office."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.dive_van import dive_van
from helpers.reading import frame_reader

_van = frame_reader(dive_van, "lee")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "need something to measure voltage on the lift control panel, anyone got one spare "
        "for 10 min",
        "need something to measure voltage on the van battery terminals",
        "could I borrow something to measure voltage on the lift control panel",
    ],
)
def test_the_thing_found_by_its_purpose_is_asked_for(text: str) -> None:
    frame = _van(text)
    assert frame.decline is None, frame.decline
    assert [(t.item, t.recipient) for t in frame.tasks] == [("multimeter", "lee")], frame


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("I need something to charge my phone battery", ["data_cable"]),
        # must not change: one noun, and a second thing joined by "and"
        ("I need something to charge my phone", ["data_cable"]),
        ("need something to charge my phone and a stapler", ["data_cable", "stapler"]),
    ],
)
def test_default_office_purposes(text: str, items: list[str]) -> None:
    frame = _default(text)
    assert frame.decline is None, frame.decline
    assert [t.item for t in frame.tasks] == items, frame
