"""A message that opens by addressing a colleague (blind round 28's class, on an office no
sentence was written for, ``helpers.rota_desk``): "Otto, could the robot bring me your
ruler?" asks for Otto's ruler (his "your"), Otto asked as its owner; without the address
"your" is read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Otto, could the robot bring me your ruler?", "otto"),
        ("Otto - can I borrow your ruler?", "otto"),
        ("Otto: can I borrow your ruler please", "otto"),
        ("hey Bill, can the robot fetch your ruler for me?", "bill"),
        ("Mark, can I borrow your ruler", "mark"),
    ],
)
def test_your_is_the_addressed_colleagues(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", owner, "ada")
    ], frame


def test_the_addressed_colleagues_ruler_may_go_to_someone_else() -> None:
    frame = _frame("Otto, can I borrow your ruler and bring it to Bill")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "otto", "bill")]


@pytest.mark.parametrize(
    "text",
    ["could the robot bring me your ruler?", "Otto could you bring me your ruler"],
)
def test_without_an_address_your_is_nobodys_in_particular(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [("ruler", None)]


def test_a_named_owner_still_decides() -> None:
    frame = _frame("Otto, bring me Bill's ruler")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "bill", "ada")]


@pytest.mark.parametrize(
    "text",
    [
        "Otto, thanks for your ruler",
        "Otto, can I borrow your ruler? never mind",
        "Otto, is your ruler in the crew room?",
    ],
)
def test_an_address_asks_nothing_by_itself(text: str) -> None:
    assert _frame(text).tasks == []
