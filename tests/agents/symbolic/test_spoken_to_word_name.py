"""A name said first and set off, then "your", is the owner (blind round 57-58's class; the
round's own offices and sentences were never read): "Miles, I need your drill" means Miles's
drill, asked of Miles, also when the name is an ordinary word ("Miles", "Ivy"). Without "your"
the thing is still anyone's; an ordinary word not set off at the start is still the word."""

from __future__ import annotations

import pytest

from assistantx.core.name_reading import NameSlot, read_name
from helpers.reading import frame_reader
from helpers.staff_room import staff_room

_frame = frame_reader(staff_room, "ravi")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Tariq, I need your drill for the plinth. Could the robot fetch it?", "tariq"),
        ("Miles, I need your drill for the plinth. Could the robot fetch it?", "miles"),
        ("Miles, I need your drill", "miles"),
        ("Ivy - can I borrow your drill?", "ivy"),
        ("Ivy: could the robot bring me your drill", "ivy"),
        ("Miles, your torch please", "miles"),
        ("hi Ivy, I need your drill, could you fetch it?", "ivy"),
    ],
)
def test_your_is_the_one_spoken_to(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (frame.tasks[0].item, owner, "ravi")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Miles, can you bring me a drill",
        "Tariq, can you bring me a drill",
        "Ivy, bring me a drill",
        "I need a drill, miles away from here",
    ],
)
def test_without_your_it_is_anyones(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [("drill", None)], frame


@pytest.mark.parametrize(
    ("slot", "reading"),
    [
        (NameSlot("miles", "Miles", opens=True, next="i", next_after_pause=True), "person"),
        (NameSlot("ivy", "Ivy", opens=True, next="can", next_after_pause=True), "person"),
        # no pause: "May I ...", "Will you ...", read as before
        (NameSlot("may", "May", opens=True, next="i"), "word"),
    ],
)
def test_a_name_word_set_off_at_the_start_is_spoken_to(slot: NameSlot, reading: str) -> None:
    assert read_name(slot) == reading
