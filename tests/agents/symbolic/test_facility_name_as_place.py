"""A facility's own name is the place, not its service (fix154b, class 4, guarded: the class's
analogues already read right on main; the measured office was never read): a thing fetched
"from the packing store", where the packing store packs lots for collection and keeps bubble
wrap for anyone, is fetched from there, never packed; the service's own verb still asks for
it."""

from __future__ import annotations

import pytest

from helpers.kit_station import kit_station
from helpers.reading import frame_reader

_station = frame_reader(kit_station, "eilidh")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Bring me some bubble wrap from the packing store, please.", "bubble_wrap"),
        ("grab me some tape from the copy room", "tape"),
        ("a bag from the binding room pls", "bag"),
        ("could you get me some bubble wrap out of the packing store", "bubble_wrap"),
    ],
)
def test_a_supply_from_a_facility_named_by_its_service_is_fetched(text: str, item: str) -> None:
    frame = _station(text)
    assert [(t.kind, t.item, t.recipient, t.operation) for t in frame.tasks] == [
        ("transfer", item, "eilidh", None)
    ], frame


# -- must not change: the service asked by its verb ------------------------------------------
def test_the_service_verb_still_asks_for_the_service() -> None:
    frame = _station("can you pack my lot", "callum")
    assert [(t.item, t.operation) for t in frame.tasks] == [("lot", "pack")], frame
