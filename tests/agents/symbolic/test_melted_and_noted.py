"""Round 251's "melt down the ring in Colin's job bag, it's going in the scrap" was kept as a
note: any verb before "down" was read as writing down ("jot this down"). Only a verb of writing
keeps a note; a verb that destroys a colleague's thing (``destructive_of_others``, now with
"melt down", "scrap", "dismantle") is declined, also where the thing is said to be in the
colleague's container."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("melt down Wang's stapler", "melt down Wang Fang's things"),
        ("melt down the stapler in Wang's drawer, it's going in the scrap", "melt down Wang"),
        ("rip up the document in Zhang's folder", "rip up Zhang Wei's things"),
        ("can you scrap Zhang's stapler", "scrap Zhang Wei's things"),
        ("dismantle Wang's stapler pls", "dismantle Wang Fang's things"),
    ],
)
def test_destroying_a_colleagues_thing_is_declined(text: str, said: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert f"I won't {said}" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "jot this down: Priya is off on Friday",
        "Mark this down please: Wang's umbrella is in the kitchen",
        "write it down: the printer is out of toner",
    ],
)
def test_a_verb_of_writing_down_keeps_a_note(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted."), frame


def test_melting_a_thing_down_is_no_note() -> None:
    frame = _frame("melt down Wang's stapler")
    assert not (frame.decline or "").startswith("Noted."), frame
