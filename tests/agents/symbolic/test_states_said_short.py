"""A state told in chat shorthand is a statement (blind round 19's "UV bulb's gone"): "'s" for
"is" before a word of state that ends its clause, and a subject without its article ("kettle
is broken"), for things the office does not know. Nothing is fetched, nothing asked; a
possessive before a described item ("Rory's broken stapler") and the office's own items and
places keep their own readings."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "UV bulb's gone",
        "fyi the kettle's broken though",
        "kettle is broken",
        "projector bulb has gone again",
        "heads up, hall clock's stopped. whiteboard's dead too",
    ],
)
def test_a_state_in_shorthand_is_noted_and_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bulb's gone", "bulb is gone"),
        ("the scanner's down again btw", "the scanner is down again btw"),
        ("Rory's broken stapler", "Rory's broken stapler"),  # a possessive, kept
        ("it's gone", "it's gone"),  # a pronoun's own contraction, kept
        ("mine's broken", "mine's broken"),
        ("Miles's missing keys", "Miles's missing keys"),
        ("hall clock's stopped.", "hall clock has stopped."),
        ("jonno's asked for one", "jonno's asked for one"),  # "has asked for": read elsewhere
    ],
)
def test_only_a_state_that_ends_its_clause_reads_as_is(text: str, expected: str) -> None:
    assert contracted_is(text)[0] == expected


def test_a_request_beside_the_state_is_still_done() -> None:
    frame = _frame("kettle's broken, can you bring me Rory's stapler")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "rory", "ada")
    ]
