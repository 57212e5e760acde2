"""A colleague said to have one ("need scissors for 2 min, Sun Li has a pair", "I think Zhang
has one", "Wang's got a spare stapler") names whom to borrow from, as "Sun Li's scissors"
would: another colleague's was taken before. A colleague said to have one the office knows
nothing of is asked about; a colleague said to have another thing, or the one it is for,
changes nothing."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("need scissors for 2 min, Sun Li has a pair", "scissors", "sun"),
        ("need scissors for 2 min, Chen has a pair", "scissors", "chen"),
        ("I need a stapler, I think Zhang has one", "stapler", "zhang"),
        ("I need a stapler, Wang has one", "stapler", "wang"),
        ("could I get a stapler? Hu Jing's got a spare", "stapler", "hu"),
        ("Gao's got a spare stapler, could you grab it for me", "stapler", "gao"),
        ("can you get me a data cable, Zhou has some", "data_cable", "zhou"),
    ],
)
def test_the_colleague_said_to_have_one_is_the_owner(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "need scissors for 2 min, Wang has a pair",  # Wang has no scissors here
        "I need a stapler, I think Chen has one",
    ],
)
def test_a_colleague_said_to_have_one_they_lack_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Where should I get one from?" in frame.question


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("I need a stapler", None, "lee"),  # nobody named: anyone's, as before
        ("bring me scissors, Wang has a stapler", None, "lee"),  # another thing
        ("give Zhang a stapler, Zhang has none", None, "zhang"),
        ("I need Hu's stapler, Zhang has one too", "hu", "lee"),  # owner said already
    ],
)
def test_near_misses_keep_their_reading(text: str, owner: str | None, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.owner, t.recipient) for t in frame.tasks] == [(owner, recipient)], frame
