"""A hope about a colleague's own thing (blind rounds 20 to 22's class, on a conservation
department no sentence was written for, ``helpers.conservation_lab``): "really hope Otto gets
his phone back from lost property, he's lost without it" asks nobody for anything; on main
Otto was asked to hand his phone over. Answered in words, nobody asked, nothing moved. A hope
that asks the assistant or is for the speaker is still read as the request it is."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.reading import frame_reader

_frame = frame_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    "text",
    [
        "really hope Otto gets his phone back from lost property, he's lost without it",
        "I really hope Clay gets his phone back",
        "hoping Joss finds his battery before the shoot",
        "so hope Bea's checklist turns up, she needs it today",
        "I do hope Rafi gets his phone fixed soon",
        "I wish Otto would get his phone back, he's lost without it",
        "wish Bea could find her checklist",
    ],
)
def test_a_hope_about_a_colleagues_thing_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("I hope you can bring me Joss's checklist", "checklist", "joss"),
        ("hope it's no trouble, could you bring me Otto's phone", "phone", "otto"),
        ("hoping Joss can lend me his battery", "battery", "joss"),
    ],
)
def test_a_hope_that_asks_is_still_read(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [(item, owner)] or frame.question, frame
