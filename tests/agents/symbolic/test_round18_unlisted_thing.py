"""Blind round 18, class 3: a thing asked for from a facility that the office does not have
("bring me 50 ml of chloroform from the chem store", where the reagent store only makes 70%
ethanol) is declined by name; never swapped for what the facility makes
(``reading.unlisted_thing``, on ``helpers.histology_lab``; the round's own office and sentences
were never read)."""

from __future__ import annotations

import pytest

from helpers.histology_lab import histology_lab
from helpers.reading import frame_reader

_frame = frame_reader(histology_lab, "bea")


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        ("can you bring me 50 ml of chloroform from the chem store", "chloroform"),
        ("can you bring me some xylene from the reagent store", "xylene"),
        ("grab me a litre of acetone out of the chem store please", "acetone"),
    ],
)
def test_an_unlisted_thing_is_declined_by_name(text: str, thing: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.decline is not None and thing in frame.decline
    assert "70% ethanol" in frame.decline  # what the store has, said, not brought


@pytest.mark.parametrize(
    "text",
    [
        "bring me 50 ml of ethanol from the chem store",
        "get me some from the chem store",
        "can you get me one from the reagent store",
    ],
)
def test_what_the_store_makes_is_still_made(text: str) -> None:
    assert [(t.kind, t.item, t.recipient) for t in _frame(text).tasks] == [
        ("produce", "ethanol", "bea")
    ]


def test_a_question_about_the_store_moves_nothing() -> None:
    assert _frame("does the chem store have any chloroform?").tasks == []
