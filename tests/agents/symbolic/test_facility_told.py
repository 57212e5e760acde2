"""A statement whose subject is a facility, by its name or a synonym, with "'s" for "has"/"is"
("popcorn machine's been beeping for an hour, driving me nuts", "coffee machine's been making a
weird noise all day") is told of the facility: words, never an order for what it makes, though
its name holds the product's (it asked what to do). Asking for the product, even naming the
facility, is read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader
from helpers.site_cabin import site_cabin

_WHO = {default_office: "lee", harbour_office: "will", site_cabin: "tamsin"}


@pytest.mark.parametrize(
    ("office", "text"),
    [
        (site_cabin, "popcorn machine's been beeping for an hour, driving me nuts"),
        (site_cabin, "the popcorn machine's making a horrible smell"),
        (site_cabin, "popper's been jammed all morning"),  # its synonym
        (default_office, "coffee machine's been making a weird noise all day"),
        (default_office, "the water dispenser's been leaking since lunch"),
        (default_office, "coffee machine has been beeping all day"),
        (default_office, "vending machine's not working again"),
        (harbour_office, "kettle's been making a funny noise"),
        (harbour_office, "the franking machine's been jammed since Monday"),
    ],
)
def test_a_statement_about_a_facility_is_words(office: OfficeOf, text: str) -> None:
    frame = frame_reader(office, _WHO[office])(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    ("office", "text", "product"),
    [
        (site_cabin, "can I have some popcorn?", "popcorn"),
        (site_cabin, "popcorn machine's popcorn for me please", "popcorn"),
        (default_office, "can you get me a coffee from the coffee machine", "coffee"),
        (harbour_office, "tea please", "tea"),
    ],
)
def test_the_product_asked_for_is_still_made(office: OfficeOf, text: str, product: str) -> None:
    frame = frame_reader(office, _WHO[office])(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", product)], frame
