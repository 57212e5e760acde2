"""A scene-setting sentence that says where someone is with "'s" for "is" ("Chen's back from
the offsite", "Chen's off to the sim tomorrow") is a statement about them, not their
possessive: it neither blocks the complete request after it with a question about words it
does not know ("off to the sim tomorrow"), nor becomes a request for their own thing (the
item named later, "Chen's stapler back", taken to the requester). Blind rounds 43-48's class;
the sentences here are the tests' own."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Morning! Chen's back from the offsite and needs a stapler. Can you take him Zhang's?",
        "Chen's back from leave and needs a stapler, can you take him Zhang's?",
        "Hi. Chen's off to the sim tomorrow and asked me to sort him a stapler. Could you "
        "borrow Zhang's and take it to him? He said it's fine.",
        "Chen's off to the client site tomorrow and asked me to find him a stapler. Could you "
        "borrow Zhang's and take it to him?",
        "Chen's back. Can you take him Zhang's stapler?",
        # said in full, as before
        "Chen is off to the sim tomorrow and asked me to sort him a stapler. Could you borrow "
        "Zhang's and take it to him?",
    ],
)
def test_the_request_after_the_scene_is_read(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "chen")
    ], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Chen's away today, could you bring me his stapler", "chen"),
        ("Chen's away till Monday. bring me his stapler", "chen"),
        ("can you bring me Zhang's stapler", "zhang"),
        ("bring me Zhang's stapler, Chen's is broken", "zhang"),
    ],
)
def test_possessives_and_absences_are_read_as_before(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", owner, "lee")], (
        frame
    )
