""" "I've lost mine" after a request for a colleague's thing is the reason for it, not news
that it is had already (blind rounds 20 to 22's class, on a conservation department no
sentence was written for, ``helpers.conservation_lab``): "can you bring me Joss's checklist?
I've lost mine" fetches Joss's checklist, Joss asked; on main the "'ve" was read as "I have
mine" and the request dropped. "I've got one", "I have mine now" still withdraw it."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.reading import frame_reader

_frame = frame_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can you bring me Joss's checklist? I've lost mine", "checklist", "joss"),
        ("can you bring me Bea's checklist? mine's gone missing", "checklist", "bea"),
        ("bring me Mina's battery, I've lost mine", "battery", "mina"),
        ("could you get me Otto's checklist please, I've just misplaced mine", "checklist", "otto"),
        ("bring me Bea's battery. I have broken mine", "battery", "bea"),
    ],
)
def test_the_reason_keeps_the_request(text: str, item: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "nell")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me Joss's checklist? oh I've got one already",
        "bring me Mina's battery. actually I have mine now",
        "bring me Mina's battery. actually I've found mine",
    ],
)
def test_had_already_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline
