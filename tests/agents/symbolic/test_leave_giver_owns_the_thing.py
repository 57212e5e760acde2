"""A colleague reported as letting the speaker have "the" thing ("Zhang said I could borrow the
stapler, can you bring it") names whose it is where they own one of that kind: "it" was read
as anyone's, and another colleague's stapler was fetched (round 240: "Baker said I could
borrow the cake knife" brought Sandy Cook's). Where the colleague owns none, "the" thing stays
anyone's, and a leave reported with the owner's own word ("his") reads as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("Zhang said I could borrow the stapler, can you bring it", "stapler", "zhang"),
        ("zhang told me I could take the stapler, pls bring it to me", "stapler", "zhang"),
        ("Wang said i can use the stapler, grab it for me?", "stapler", "wang"),
        ("Yang said I could borrow the book, can u bring it", "book", "yang"),
        ("Yang said I could borrow his book, can u bring it", "book", "yang"),
    ],
)
def test_the_thing_the_giver_owns_is_theirs(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Chen said I could borrow the stapler, can you bring it",  # Chen owns no stapler
        "Zhang said the stapler is jammed, can you bring me one",  # no leave reported
    ],
)
def test_without_a_giver_who_owns_one_it_stays_anyones(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "stapler", None)], (
        frame
    )
