"""The speaker's own thing left outside the office, said as a fact beside why it is wanted
now ("my phone's on 2% and i left my cable at home", round 216's default-office class, read
after its measure), is met with an offer of one a colleague could lend or a cupboard keeps
("Shall I bring you one?") and comes on a yes; it was only noted ("your data cable is out of
use. I did nothing."). Nothing moves on the statement alone; said alone or after an
exclamation it is news (round 40's "gosh, I left my stapler at home"), and a thing left at a
place in the office, a thing nobody lends (a lunch) and a request beside it are read as
before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import answered_reader, frame_reader

_hu = frame_reader(load_office, "hu")  # Hu has no data cable; Dang and Zhou have one
_answered = answered_reader(load_office, "hu")


@pytest.mark.parametrize(
    "text",
    [
        "my phone's on 2% and i left my cable at home",
        "laptop nearly dead and I forgot my cable again",
        "my phone is dying and i left my cable in the car",
        "got a call in five and i forgot my cable",
    ],
)
def test_a_thing_left_behind_is_offered(text: str) -> None:
    frame = _hu(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None, frame
    assert "Shall I bring you one?" in frame.question and "data cable" in frame.question
    assert "Dang Hao" in frame.question and "_" not in frame.question, frame


def test_the_offer_brings_one_on_a_yes() -> None:
    frame = _answered("my phone's on 2% and i left my cable at home", ["yes please"])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "data_cable", "hu")
    ], frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        # news: nothing said of why it is wanted now
        ("i left my cable at home", "your data cable is out of use"),
        ("I forgot my cable", "your data cable is out of use"),
        ("ugh i left my cable in the car", "your data cable is out of use"),
        # where it is in the office, not a lack
        ("i left my cable at my desk", "your data cable is out of use"),
        ("i left my stapler in the meeting room", "your stapler is out of use"),
        # nobody lends a lunch
        ("I forgot my lunch again", "your lunch is out of use"),
        ("i can't find my stapler", "your stapler is out of use"),
    ],
)
def test_what_is_not_left_behind_is_noted_as_before(text: str, said: str) -> None:
    frame = _hu(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and said in frame.decline, frame


def test_a_request_beside_it_is_read_as_before() -> None:
    frame = _hu("i left my cable at home, can i borrow Dang's")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "data_cable", "dang", "hu")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        # round 226's class (read after its final measure): the speaker's own thing out of use
        # after a clause of their situation; it had asked where Frank's head torch was
        "meeting at Pryce's tonight and my stapler is broken. could someone lend me one",
        "in a rush and my stapler is dead, can i borrow one",
    ],
)
def test_a_broken_thing_after_the_situation_is_a_fact_and_one_is_borrowed(text: str) -> None:
    frame = _hu(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", None, "hu")
    ], frame


def test_a_broken_thing_after_the_situation_alone_is_noted() -> None:
    frame = _hu("i'm in a rush and my stapler is broken")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "your stapler is out of use" in frame.decline
