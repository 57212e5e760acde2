"""A colleague's want said as lasting till now ("Gwen's been after the archive key all
morning", "Zhang has been after a cable") is their want now, read as "is after" (reading/
purpose.py ``contracted_needs``): what they are after is the thing "it" or "one" names, any
one of the office's, and the colleague the receiver (fix61f class 4: "it" was read as Gwen's
own key and whose it was asked). The speaker's own ("I've been after a stapler") and a state
("Wang's stapler has been broken") are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_frame = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("Wang's been after the stapler all day, can you take it to her", "stapler", "wang"),
        ("Wang has been after the stapler all day, can you take it to her", "stapler", "wang"),
        ("Zhang has been after a cable, bring him one", "data_cable", "zhang"),
        ("Zhang's been looking for the scissors, can you take them to him", "scissors", "zhang"),
    ],
)
def test_a_lasting_want_names_the_receiver_of_any_one(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, None, recipient)], frame


@pytest.mark.parametrize("text", ["I've been after a stapler all day", "Wang has been after lunch"])
def test_no_colleagues_want_is_no_errand(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is None, frame


def test_a_state_said_with_has_been_is_still_a_fact() -> None:
    frame = _frame("Wang's stapler has been broken")
    assert not frame.tasks and frame.decline is not None and "broken" in frame.decline, frame
