"""A colleague named in one clause, then asked by "she"/"he" to have the requester's thing
("Wang's covering the front desk, could she have my stapler?"): the colleague is the one it
is given to, the requester its owner; never the colleague's own thing brought back.
"could I have her stapler" still borrows hers for the requester."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("Wang's covering the front desk, could she have my stapler?", "stapler", "wang"),
        ("Chen's running the stall - could he have my scissors?", "scissors", "chen"),
        ("Wang is helping out downstairs. Can she borrow my stapler?", "stapler", "wang"),
        (
            "Zhang's running the stall - could he have my scissors? just drop them off",
            "scissors",
            "zhang",
        ),
    ],
)
def test_she_asked_to_have_my_thing_is_its_recipient(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "lee", recipient)
    ], frame


def test_i_asked_to_have_hers_still_borrows_hers() -> None:
    frame = _frame("Wang's covering the front desk, could I have her stapler?")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "lee")]


def test_two_people_named_before_the_pronoun_is_not_guessed() -> None:
    frame = _frame("Wang and Chen are running the stall, could she have my stapler?")
    assert not [t for t in frame.tasks if t.recipient in ("wang", "chen")], frame
