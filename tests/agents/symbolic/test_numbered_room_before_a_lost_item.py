"""Blind rounds 43-48, class J3: a statement opening with a numbered room or thing ("Court 3
is locked and I can't find my keys"), then a request for one ("can someone get me a set?"):
"Court 3" is the statement's subject like "the lab" (``speech.statement``), though "court"
or "room" alone may be a verb, so the statement is context and the request is for anyone's
keys, never a move of the requester's own lost ones (on ``helpers.county_court``; the rounds'
own offices and sentences were never read). A request's verb and its count ("print 3
copies") are no subject, and the requester's own thing asked for by "my" stays their own."""

from __future__ import annotations

import pytest

from helpers.county_court import county_court
from helpers.reading import frame_reader

_frame = frame_reader(county_court, "tess")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Court 3 is locked and I can't find my keys. Can someone get me a set?", "courtroom_keys"),
        ("Room 3 is locked and I can't find my keys. Can someone get me a set?", "courtroom_keys"),
        (
            "Court 3's locked and I've lost my keys - could someone bring me a set?",
            "courtroom_keys",
        ),
        ("Bay 2 is shut and I can't find my stapler, can someone bring me one?", "stapler"),
        ("court 3 was locked and I've misplaced my keys, could I get a set?", "courtroom_keys"),
        ("The lab is locked and I can't find my keys. Can someone get me a set?", "courtroom_keys"),
    ],
)
def test_anyones_one_is_brought(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "tess")
    ], frame.question


def test_the_statement_alone_moves_nothing() -> None:
    frame = _frame("Court 3 is locked and I can't find my keys.")
    assert frame.tasks == []
    assert frame.question is None


@pytest.mark.parametrize("text", ["bring me my stapler from my desk", "bring me my stapler"])
def test_my_own_is_still_mine(text: str) -> None:
    frame = _frame(text)
    assert all(t.owner != None for t in frame.tasks)  # noqa: E711
