""" "something/anything" with words that describe it, from a facility that makes one kind of
thing from nothing, is that kind: "grab me something salty from the vending machine" was
declined ("there is no salty at the vending machine") and "anything hot from the coffee
machine" was read as a service nobody offers. The describing words say only which of the
facility's things; a word that names a party ("something for Wang from ...") is no
description and keeps its meaning. Without a facility named, nothing changes."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "made"),
    [
        ("get me something sweet from the vending machine", "snack"),
        ("grab me something salty from the vending machine", "snack"),
        ("anything hot from the coffee machine", "coffee"),
        ("could you fetch me something salty and crunchy from the snack machine", "snack"),
        ("something cold, fresh from the water cooler please", "water"),
    ],
)
def test_described_something_from_a_one_kind_facility_is_that_kind(text: str, made: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert frame.decline is None, frame.decline
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", made, "lin")]


def test_on_harbour_the_kettle_gives_its_tea() -> None:
    frame = _harbour("can you get me something hot from the kettle")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "will")]


def test_a_party_between_is_no_description() -> None:
    """ "for Wang" says whom the snack is for: it stays Wang's, not swallowed as a description."""
    frame = _default("could you get me something for Wang from the vending machine")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "snack", "wang")]


def test_without_a_facility_nothing_changes() -> None:
    """Neighbour: "a salty pretzel" with no facility is a thing the office lacks, as before."""
    frame = _default("get me a salty pretzel")
    assert frame.tasks == []
    assert frame.decline is not None or frame.question is not None


def test_bare_anything_from_a_machine_is_not_rewritten() -> None:
    """ "anything from the coffee machine for me?" may ask whether something came: no coffee."""
    frame = _default("anything from the coffee machine for me?")
    assert all(t.item != "coffee" for t in frame.tasks) or frame.question is not None
