"""A supply named in the plural matches the singular asked, word by word by its lemmas, for a
name of several words too (round 143 class 2): "a scalpel blade" is one of the cupboard's
"scalpel blades" though a scalpel is another thing of the office, and "a blade" from a
cupboard whose one such supply is scalpel blades is one of them; never "there is no blade
... It has scalpel blades". A word that only modifies a supply's name ("a cable" where only
cable ties are kept) is still declined with what the cupboard has."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.supply_cupboard import supply_cupboard

_read = frame_reader(supply_cupboard, "rhea")


@pytest.mark.parametrize(
    ("text", "supply"),
    [
        ("cna you grab me a scalpel blade from stores, mine snapped", "scalpel_blades"),
        ("a scalpel blade please", "scalpel_blades"),
        ("grab me a cable tie from the cupboard", "cable_ties"),
        ("an AA battery from stores pls", "aa_batteries"),  # a power bank is "battery"
        ("can I get a sticky note from the cupboard", "sticky_notes"),
        ("a craft knife from the cupboard please", "craft_knives"),  # a palette "knife"
        ("bring me a storage box from stores", "storage_boxes"),
        # the head noun alone, where one supply of the cupboard ends in it
        ("a blade from the cupboard please", "scalpel_blades"),
        ("grab me some blades from stores", "scalpel_blades"),
        ("grab me a box from stores", "storage_boxes"),
    ],
)
def test_the_singular_is_the_plural_supply(text: str, supply: str) -> None:
    frame = _read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", supply)], frame.tasks


# -- must not change ---------------------------------------------------------------------


def test_a_modifier_of_a_supplys_name_is_no_such_supply() -> None:
    frame = _read("a cable from the cupboard")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, there is no cable at the materials cupboard")
    assert "cable ties" in frame.decline


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Bram's battery", "power_bank", "bram"),
        ("bring me Bram's knife", "knife", "bram"),
    ],
)
def test_the_shorter_things_name_alone_is_that_thing(text: str, item: str, owner: str) -> None:
    frame = _read(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [(item, owner)], frame
