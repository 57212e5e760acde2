"""A made thing asked for by where it comes from: "something from the vending machine" is
the one kind of thing that machine makes (a snack), so "glass of water please, and something
from the vending machine" brings both; before, the second part was read as a statement and
dropped in silence (blind round 76's default-office sentences). A machine that makes several
kinds (the printer: printouts and copies), or makes its thing from someone's item, keeps the
words as said and is asked about."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "liu")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "made"),
    [
        ("glass of water please, and something from the vending machine", ["water", "snack"]),
        ("something from the vending machine please", ["snack"]),
        ("could you get me something out of the coffee machine", ["coffee"]),
    ],
)
def test_something_from_a_machine_that_makes_one_kind_is_that_kind(
    text: str, made: list[str]
) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", item, "liu") for item in made
    ]


def test_something_from_a_machine_that_makes_several_kinds_is_asked_about() -> None:
    frame = _default("grab me something from the printer")
    assert frame.tasks == [] and frame.question is not None


def test_anything_from_a_machine_stays_as_said() -> None:
    """ "anything from the coffee machine for me?" may ask whether something came: no guess."""
    frame = _default("anything from the coffee machine for me?")
    assert all(t.item != "coffee" for t in frame.tasks) or frame.question is not None


def test_the_same_on_harbour() -> None:
    """Harbour's kettle makes tea from nothing: "something from the kettle" is a tea; its
    printer prints someone's file, so "something from the printer" is still asked about."""
    tea = _harbour("something from the kettle please")
    assert [(t.kind, t.item, t.recipient) for t in tea.tasks] == [("produce", "tea", "will")]
    printed = _harbour("something from the printer please")
    assert printed.tasks == [] and printed.question is not None
