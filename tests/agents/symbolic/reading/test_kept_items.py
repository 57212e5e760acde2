"""What the office keeps at a facility or a place, the one lookup behind "the kettle in the
kitchen" and "Jürgen's curry from the staff fridge": a facility's supplies still in stock,
people's belongings a facility keeps, and at a place, what lies on the desks there."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.kept_items import KeptItem, items_kept_at
from assistantx.core.office import parse_office
from helpers.hostel import hostel
from helpers.printshop import raw_printshop


def test_a_facility_keeps_its_supplies_then_the_belongings_it_keeps() -> None:
    assert items_kept_at(hostel(), "facility", "post_desk") == [
        KeptItem("parcel", "post_desk", "supply"),
        KeptItem("pump", "yusuf", "keeper"),
    ]


def test_a_place_keeps_what_its_facilities_keep() -> None:
    kept = items_kept_at(hostel(), "place", "kitchen")
    assert kept == [KeptItem("kettle", "kitchen_counter", "supply")]


def test_a_facility_elsewhere_keeps_nothing_here() -> None:
    assert items_kept_at(hostel(), "facility", "laundry_shelf") == [
        KeptItem("iron", "laundry_shelf", "supply")
    ]
    assert items_kept_at(hostel(), "place", "laundry") == [
        KeptItem("iron", "laundry_shelf", "supply")
    ]


def test_a_workstation_keeps_what_lies_on_its_desk() -> None:
    # Yusuf's bike pump is kept at the post desk, not on his desk; his ladder and files are.
    kept = items_kept_at(hostel(), "place", "desk_6")
    assert kept == [
        KeptItem("ladder", "yusuf", "desk"),
        KeptItem("rota", "yusuf", "desk"),
        KeptItem("notice", "yusuf", "desk"),
    ]
    assert items_kept_at(hostel(), "facility", "desk_6") == []


def test_a_supply_used_up_is_not_kept_there() -> None:
    raw = raw_printshop()
    for f in raw["facilities"]:
        if f["id"] == "paper_store":
            f["supplies"] = [{"type": "card_stock", "count": 0}, {"type": "string"}]
    office = parse_office(raw, "printshop")
    assert items_kept_at(office, "facility", "paper_store") == [
        KeptItem("string", "paper_store", "supply")
    ]
