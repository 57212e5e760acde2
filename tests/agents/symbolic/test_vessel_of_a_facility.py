"""A vessel of a facility's product, the product named by the facility (round 59's class,
fixer fix59b; the round's own sentences were never read): "fill me a wash bottle of milli-q",
"a jug from the urn", "a flask of the dewar" were declined "there is no bottle at the Milli-Q
unit". A vessel the office does not list, said of or from a facility that makes one thing to
be poured, asks for that thing, brought to the speaker (``unlisted_thing.vessel_of``). A cup
that is an office item, a product named ("a bottle of deionised water"), a facility that
makes nothing and one whose one product is not poured (printouts) are read as before."""

from __future__ import annotations

import pytest

from helpers.bench_wing import wing
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_frame = frame_reader(wing, "rafe")
_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "grace")


@pytest.mark.parametrize(
    ("text", "product"),
    [
        ("fill me a wash bottle of milli-q pls", "di_water"),
        ("pour me a jug from the urn", "hot_water"),
        ("a jug of the urn please", "hot_water"),
        ("fill me a flask of the dewar", "ln2"),
        ("could you get me a thermos from the filter machine", "filter_coffee"),
    ],
)
def test_a_vessel_of_a_facility_is_its_product(text: str, product: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", product, "rafe")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "product"),
    [
        ("a jug of water dispenser please", "water"),
        ("fill me a flask of the water cooler", "water"),
    ],
)
def test_in_the_default_office(text: str, product: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", product, "lee")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("bring me a cup", "transfer", "cup"),  # a cup is an item of the office
        ("a bottle of deionised water please", "produce", "di_water"),
        ("fill me a bottle of liquid nitrogen", "produce", "ln2"),
    ],
)
def test_items_and_products_named_are_read_as_before(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame


def test_a_facility_that_makes_nothing_gives_no_product() -> None:
    frame = _frame("a flask from the fume hood please")
    assert frame.tasks == [], frame


def test_a_store_that_keeps_supplies_still_declines_the_vessel() -> None:
    frame = _frame("a bottle from the tool store")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "no bottle" in frame.decline, frame


def test_a_product_that_is_not_poured_still_declines_the_vessel() -> None:
    frame = _harbour("a bottle from the printer")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "no bottle" in frame.decline, frame
