"""A complaint about a facility ("the shredder's making a horrible grinding noise again", "the
kettle keeps tripping the fuse", "shredder's jammed AGAIN") is told, not asked: answered in
words, with what the assistant cannot do about it (blind rounds 61-62's class: the first read
as asking for a service "shredders making" and was refused). A request beside it is read as
before."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("the shredder's making a horrible grinding noise again", "making a horrible grinding"),
        ("the shredder is making that clunking sound again", "making that clunking sound"),
        ("shredder's jammed AGAIN", "jammed"),
        ("the kettle keeps tripping the fuse", "keeps tripping the fuse"),
        ("the kettle's leaking everywhere lol", "leaking everywhere"),
        ("the vending machine's eating my coins again", "eating your coins"),
        ("the coffee machine is out of order", "out of order"),
    ],
)
def test_a_complaint_is_answered_in_words(text: str, said: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and said in frame.decline, frame
    assert "can't repair" in frame.decline, frame


def test_a_facility_at_its_work_is_told_with_nothing_wrong() -> None:
    frame = _frame("the kettle's boiling")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "can't repair" not in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("the shredder's making a weird noise, can you shred my invoice?", "invoice"),
        ("the coffee machine keeps beeping, could you make me a coffee", "coffee"),
    ],
)
def test_a_request_beside_a_complaint_is_read_as_before(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == [item], frame
