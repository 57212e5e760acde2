"""Vague things from a store that keeps several supplies (round 59's class, fixer fix59b; the
round's own sentences were never read): "can you grab me a few bits from the stores" was
declined "there is no bits at the tool store". A vague thing-word ("bits", "stuff", "things",
"odds and ends"), counted or qualified ("a few", "some", "a couple of", "the usual"), said of
a place that keeps several things for anyone asks which of them, naming them
(``placeholder_thing``); the answer takes the vague words' place. A supply named, a statement
about the store, and vague words of a place with one thing (its product) are read as before."""

from __future__ import annotations

import pytest

from helpers.bench_wing import wing
from helpers.dataset_offices import harbour_office
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(wing, "rafe")
_answered = answered_reader(wing, "rafe")
_harbour = frame_reader(harbour_office, "grace")


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("can you grab me a few bits from the stores", "a few bits"),
        ("bring me some stuff from the kit room", "some stuff"),
        ("grab a couple of things from the kit room for me", "a couple of things"),
        ("get me the usual bits from the store", "the usual bits"),
        ("could you get me some odds and ends from the store", "some odds and ends"),
    ],
)
def test_vague_things_from_a_store_ask_which(text: str, said: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None and frame.question is not None, frame
    assert f"“{said}”" in frame.question, frame
    for supply in ("drill", "sandpaper", "ear defenders"):
        assert supply in frame.question, frame


def test_the_answer_names_the_supply() -> None:
    frame = _answered("can you grab me a few bits from the stores", ["some sandpaper"])
    assert [(t.item, t.recipient) for t in frame.tasks] == [("sandpaper", "rafe")], frame


def test_a_named_supply_is_read_as_before() -> None:
    frame = _frame("bring me some tape from the store")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "tape", "rafe")], (
        frame
    )


def test_a_statement_about_the_store_is_read_as_before() -> None:
    frame = _frame("there's no stuff left in the store")
    assert frame.tasks == [] and frame.question is None, frame


def test_a_facility_with_one_product_gives_it_as_before() -> None:
    frame = _frame("something from the urn please")
    assert [t.item for t in frame.tasks] == ["hot_water"], frame


def test_a_cupboard_with_one_product_gives_it_as_before() -> None:
    # harbour's cupboard makes notepads; a colleague's label maker kept there is no supply
    frame = _harbour("bring me some stuff from the stationery cupboard")
    assert [t.item for t in frame.tasks] == ["notepad"], frame
