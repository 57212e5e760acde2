"""A colleague's name plus "s" that is also an English word, right before an item that
colleague keeps none of ("can u grab bills ruler", Bill keeps no ruler): Bill's (which he
lacks) and the plain word (anyone's ruler) are different errands and nothing decides, so
the reader asks which (``reading.bare_possessives.doubted_possessives``). Where the colleague
keeps the item ("marks ruler") it stays their possessive; with no item right after, or with
the apostrophe, nothing is asked."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_harbour = frame_reader(harbour_office, "may")
_default = frame_reader(default_office, "lin")


@pytest.mark.parametrize(
    ("text", "name", "item"),
    [
        ("can u grab bills ruler for me", "Bill Ferreira", "ruler"),
        ("could you fetch graces tape", "Grace Huang", "tape"),
        ("can i borrow wills umbrella pls", "Will Tanaka", "umbrella"),
    ],
)
def test_harbour_a_word_name_s_before_an_item_they_lack_is_asked(
    text: str, name: str, item: str
) -> None:
    frame = _harbour(text)
    assert frame.question is not None, frame
    assert f"{name}'s {item}, or any {item}?" in frame.question, frame.question
    assert all(t.owner is None for t in frame.tasks), frame  # never Bill's, unasked


def test_default_a_word_name_s_before_an_item_they_lack_is_asked() -> None:
    # Sun Li keeps scissors, no stapler; "suns" is an English word
    frame = _default("can u grab suns stapler for me")
    assert frame.question is not None
    assert "Sun Li's stapler, or any stapler?" in frame.question, frame.question


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can u grab marks ruler for me", "mark"),  # Mark keeps a ruler: his
        ("could you fetch graces ruler", "grace"),
    ],
)
def test_harbour_one_who_keeps_the_item_is_its_owner_unasked(text: str, owner: str) -> None:
    frame = _harbour(text)
    assert frame.question is None or ", or any " not in frame.question, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "ruler", owner)]


def test_default_one_who_keeps_the_item_is_its_owner_unasked() -> None:
    frame = _default("can u grab suns scissors for me")
    assert frame.question is None or ", or any " not in frame.question, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "scissors", "sun")]


@pytest.mark.parametrize(
    "text",
    [
        "pay the bills, then grab me a ruler",  # a pause: the word ends its own phrase
        "can you bring me a ruler",
    ],
)
def test_no_item_right_after_the_word_is_not_asked(text: str) -> None:
    frame = _harbour(text)
    assert frame.question is None or ", or any " not in frame.question, frame.question


_harbour_answered = answered_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("answer", "owner"),
    [
        ("any ruler", None),
        ("doesn't matter", None),
        ("Bill's", "bill"),
        ("his", "bill"),
    ],
)
def test_the_answer_chooses_the_reading(answer: str, owner: str | None) -> None:
    frame = _harbour_answered("can u grab bills ruler for me", [answer])
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", owner, "may")
    ]


def test_an_answer_choosing_neither_asks_again() -> None:
    frame = _harbour_answered("can u grab bills ruler for me", ["hmm"])
    assert frame.question is not None and ", or any ruler?" in frame.question
    assert frame.tasks == []
