"""The speaker's own thing, broken in one of its parts, is why another is asked for: "my
calculator's screen just cracked, can somebody lend me theirs?". The item before the "'s" owns
the part ("screen", "battery", "handle"); it is no compound's modifier ("tea time"), so the
clause is a statement about that thing, and "theirs" / "one of yours" / "someone's" is anyone
else's of its kind handed to the speaker (never the speaker's own, asked where it is)."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "my calculator's screen just cracked, can somebody lend me theirs?",
        "my calculator's battery just died mid-meeting, could someone lend me one of yours?",
        "my calculator's display went blank, could anyone lend me theirs",
    ],
)
def test_a_broken_part_asks_for_anyone_elses_harbour(text: str) -> None:
    assert tasks_of("harbour", text, "will") == [("transfer", "calculator", None, "will")]


def test_a_broken_part_of_a_tape_dispenser_harbour() -> None:
    text = "my tape dispenser's blade snapped off, can I borrow someone's?"
    assert tasks_of("harbour", text, "may") == [("transfer", "tape", None, "may")]


@pytest.mark.parametrize(
    "text",
    [
        "my stapler's spring just snapped, could someone lend me theirs?",
        "my stapler's handle is cracked, could anyone lend me one of theirs",
        "my stapler jammed again, could anyone lend me one of theirs",
    ],
)
def test_a_broken_part_asks_for_anyone_elses_default(text: str) -> None:
    assert tasks_of("default", text, "zhang") == [("transfer", "stapler", None, "zhang")]


def test_the_speakers_own_thing_somewhere_is_still_fetched() -> None:
    # must not change: "my stapler's at Wang's desk" is where the speaker's own one is
    text = "my stapler's at Wang's desk, can you bring it back"
    assert tasks_of("default", text, "zhang") == [("transfer", "stapler", "zhang", "zhang")]


def test_tea_time_is_still_a_compound() -> None:
    # must not change: an item that only names a kind of thing adds no errand of its own
    assert tasks_of("default", "Tea time soon. Could you bring me a pen?", "zhang") == [
        ("transfer", "pen", None, "zhang")
    ]
