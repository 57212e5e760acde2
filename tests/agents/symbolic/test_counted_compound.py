"""A compound noun whose first word is an item's name and whose head is a plural that is
also a verb's form ("some cable ties", "cut the cable ties", where the office has a data
cable): the plural heads the phrase, so it is no request for the cable. The purpose ("to
cut") then picks the item whose purposes say it (the scissors), or a question is asked; the
data cable had been fetched. The name said as a verb's subject ("my data cable works") and
the cable asked for plainly are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


def test_a_counted_compound_is_no_request_for_its_first_noun() -> None:
    frame = _default("need to cut some cable ties, anything sharp around?")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "scissors")], frame


@pytest.mark.parametrize(
    "text",
    [
        "need to cut the cable ties, anything sharp around?",
        "bring me some cable ties",
    ],
)
def test_the_compound_never_fetches_the_cable(text: str) -> None:
    frame = _default(text)
    assert all(t.item != "data_cable" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me the data cable", "data_cable"),
        ("my data cable works fine, bring me a pen", "pen"),
        ("bring me two data cables", "data_cable"),
    ],
)
def test_the_item_itself_is_read_as_before(text: str, item: str) -> None:
    frame = _default(text)
    assert [t.item for t in frame.tasks] == [item], frame
