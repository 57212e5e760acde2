"""A thing said to be used up with "'s" for "has" and a particle ("the foil's run out at my
bench", "the marker's dried up") is a statement of that thing's state, so "a bit more", "some
more" or "another one" in the request after it is more of that thing, for the requester (blind
round 57's class; its offices and sentences were never read). A possessive before a thing
("Miles's run sheet") is untouched."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from helpers.bursary import bursary
from helpers.reading import frame_reader

_frame = frame_reader(bursary, "ana")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "Sorry to bother you, but the foil's run out at my bench. Could you grab a bit more?",
            "foil",
        ),
        ("the foil's run out. Could you grab some more?", "foil"),
        ("foil's run out at my desk, can you fetch a bit more", "foil"),
        ("the marker's dried up, can you get me another one", "marker"),
        ("my marker's run dry. could you bring another one?", "marker"),
    ],
)
def test_more_of_a_thing_used_up_is_that_thing(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "ana")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("the foil's run out at my bench", "the foil has run out at my bench"),
        ("the glue's dried up", "the glue has dried up"),
        ("Miles's run sheet is here", "Miles's run sheet is here"),
    ],
)
def test_the_contraction_before_a_particle_is_has(text: str, read: str) -> None:
    assert contracted_is(text)[0] == read
