"""Blind round 83's default-office sentence "Min is out of paper, could you drop a few sheets
of mine at her desk" took "Min is out" for an absence, so the delivery to her was given up
("Gao Min known to be away"). "out of" a thing says a supply ran out; only the away phrases
that say "out of" themselves ("out of office", "out of the office") are an absence."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_READERS = {
    default_office: frame_reader(default_office, "wu"),
    harbour_office: frame_reader(harbour_office, "will"),
}


def _facts(office: OfficeOf, text: str) -> list[str]:
    return [e.meaning for e in _READERS[office](text).evidence if e.meaning.startswith("a fact")]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        (default_office, "Gao is out of paper"),
        (default_office, "Gao's out of staples"),
        (default_office, "Min is out of paper, could you bring her some of mine"),
        (harbour_office, "Rose is out of tape"),
        (harbour_office, "Pat's out of highlighters again"),
    ],
)
def test_out_of_a_thing_is_no_absence(office: OfficeOf, text: str) -> None:
    assert not any("away" in fact for fact in _facts(office, text)), _facts(office, text)


@pytest.mark.parametrize(
    ("office", "text", "who"),
    [
        (default_office, "Gao is out of office", "Gao Min"),
        (default_office, "Gao is out of the office today", "Gao Min"),
        (default_office, "Gao is out today", "Gao Min"),
        (harbour_office, "Rose is out of the office", "Rose Adeyemi"),
    ],
)
def test_out_of_the_office_is_still_away(office: OfficeOf, text: str, who: str) -> None:
    assert _facts(office, text) == [f"a fact: {who} is away"]


def test_the_delivery_to_her_goes_ahead() -> None:
    frame = _READERS[default_office]("Gao is out of paper, could you bring her some of mine")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "paper", "wu", "gao")
    ]
