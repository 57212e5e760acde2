"""A thing fetched for "me", described by where it lies (reading/placed_thing.py), and a
thing to be put beside a colleague's thing (reading/beside_a_thing.py).

"bring me the ruler at Mark's desk" sent a ruler to Mark; "bring me the ruler next to Mark's"
fetched two rulers. The indirect object receives, and the place after the thing tells which
thing: the colleague's, asked of them as of any owner. "leave the calculator beside Will's
lamp" fetched a calculator for the speaker: a placement the robot cannot make is said so, and
nothing moves. A place that receives ("bring the ruler to Mark's desk", "leave the ruler at
Mark's desk", "put the ruler next to Mark's") is read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "who"),
    [
        (_harbour, "bring me the ruler at Mark's desk", "ruler", "mark", "rose"),
        (_harbour, "bring me the ruler that's next to Mark's desk", "ruler", "mark", "rose"),
        (_harbour, "bring me the ruler next to Mark's", "ruler", "mark", "rose"),
        (
            _harbour,
            "could you get me the calculator on Will's desk please",
            "calculator",
            "will",
            "rose",
        ),
        (_default, "get me the stapler on Zhang's desk", "stapler", "zhang", "lee"),
        (_default, "bring me the cup next to Dang's", "cup", "dang", "lee"),
        (_default, "fetch me the book which is beside Yang Lei's desk", "book", "yang", "lee"),
        (_harbour, "bring me the ruler next to Mark's calculator", "ruler", "mark", "rose"),
        (_harbour, "bring me the ruler next to Mark's lamp", "ruler", "mark", "rose"),
        (_default, "grab me the scissors by Chen's monitor", "scissors", "chen", "lee"),
    ],
)
def test_the_thing_where_it_lies_is_theirs_brought_to_me(
    read: ReadFrame, text: str, item: str, owner: str, who: str
) -> None:
    frame = read(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_harbour, "bring the ruler to Mark's desk", "ruler", "mark"),
        (_harbour, "leave the ruler at Mark's desk", "ruler", "mark"),
        (_harbour, "put the ruler next to Mark's", "ruler", "mark"),
        (_default, "bring the stapler to Zhang's desk", "stapler", "zhang"),
    ],
)
def test_a_place_that_receives_is_read_as_before(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_harbour, "leave the calculator beside Will's lamp"),
        (_harbour, "put the ruler next to Mark's monitor please"),
        (_default, "pop the book beside Dang's plant"),
    ],
)
def test_a_thing_put_beside_a_thing_moves_nothing(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "desk" in frame.decline


def test_the_sentence_goes_on_after_the_bare_possessive() -> None:
    frame = _harbour("bring me the ruler next to Mark's and a highlighter")
    got = sorted((t.item, t.owner == "mark", t.recipient) for t in frame.tasks)
    assert got == [("highlighter", False, "rose"), ("ruler", True, "rose")], frame


def test_what_the_speaker_did_is_told_not_declined() -> None:
    frame = _harbour("I put the ruler next to Mark's lamp")
    assert frame.tasks == [] and "can't place" not in (frame.decline or ""), frame
