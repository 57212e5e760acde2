"""The speaker's need said as a cleft ("it's a stapler I need", "what I need is a stapler",
"it's scissors I'm after") asks for the thing for the speaker, also after a withdrawal of the
first thing ("bring me a pen - no wait i've got one, it's a stapler i need, mine jammed"); a
reason told after that new request ("mine jammed") is its reason, never the withdrawal's
(fix201b class 2: before, the cleft was a statement and the whole message a withdrawal)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.cleft_need import cleft_needs
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        # the class's own shape
        ("bring me a pen - no wait i've got one, it's a stapler i need, mine jammed", "stapler"),
        ("bring me a pen - no wait i have mine, it's scissors im after", "scissors"),
        ("bring me a pen - no wait i've got one. what I need is a stapler", "stapler"),
        ("bring me a pen - no wait i've got one, i need a stapler, mine jammed", "stapler"),
        ("it's a stapler i need", "stapler"),
        ("it's the stapler that i need", "stapler"),
        ("its a stapler i'm after", "stapler"),
        ("what i need is a stapler", "stapler"),
    ],
)
def test_the_cleft_asks_for_the_thing_for_the_speaker(text: str, item: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        # must not change: the withdrawal alone, and its reason
        "bring me a pen - no wait i've got one",
        "never mind, found one in my drawer",
        "bring me a stapler. never mind, found mine in my drawer",
    ],
)
def test_a_withdrawal_alone_still_withdraws(text: str) -> None:
    frame = _lee(text)
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    "text",
    [
        "it's not a stapler i need",  # negated: no thing asked
        "it's Zhang I need to see",  # an errand for someone, not a thing
        "what i need is to sign in",
    ],
)
def test_not_a_cleft_of_a_thing_is_left_alone(text: str) -> None:
    assert cleft_needs(text) == text
