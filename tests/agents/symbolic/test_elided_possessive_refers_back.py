"""An elided possessive refers back: "my stapler's broken, can I have Wang's? and grab me a
coffee too" asks for Wang's stapler and one coffee. Before, "Wang's" took the last thing of
the whole message (the coffee) and two coffees were made. "X's" with no noun after it is the
nearest thing named before it; a later noun fills it only where nothing came before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("text", "owner", "item", "made"),
    [
        (
            "my stapler's broken, can I have Wang's? and grab me a coffee too",
            "wang",
            "stapler",
            "coffee",
        ),
        ("my pen ran out, can I borrow Chen's? and get me a water as well", "chen", "pen", "water"),
        (
            "my stapler is jammed, could I use Zhang's? and a coffee please",
            "zhang",
            "stapler",
            "coffee",
        ),
    ],
)
def test_default_office(text: str, owner: str, item: str, made: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    kinds = {t.item: t for t in frame.tasks}
    assert len(frame.tasks) == 2, frame.tasks
    assert kinds[item].owner == owner
    assert kinds[made].kind == "produce" and kinds[made].owner is None


@pytest.mark.parametrize(
    ("text", "owner", "item"),
    [
        ("my calculator died, could I borrow Dawn's? and a tea please", "dawn", "calculator"),
        ("my charger is broken, can I have Bill's? and grab me a tea too", "bill", "charger"),
        ("my ruler snapped, could I borrow Art's? and a tea as well", "art", "ruler"),
    ],
)
def test_harbour(text: str, owner: str, item: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    kinds = {t.item: t for t in frame.tasks}
    assert len(frame.tasks) == 2, frame.tasks
    assert kinds[item].owner == owner
    assert kinds["tea"].kind == "produce"


@pytest.mark.parametrize(
    "text",
    [
        "can I have Wang's stapler and a coffee",  # the noun is said: nothing elided
        "a coffee, and Wang's stapler",
    ],
)
def test_a_possessive_with_its_noun_is_unchanged(text: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    kinds = {t.item: t for t in frame.tasks}
    assert set(kinds) == {"stapler", "coffee"} and len(frame.tasks) == 2
    assert kinds["stapler"].owner == "wang"


def test_with_nothing_before_a_later_noun_fills_it() -> None:
    frame = _default("can I have Wang's? the stapler")
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", "wang")]
