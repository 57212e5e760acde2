""" "my probes dead, need a thermometer asap": chat drops the apostrophe of "probe's", so a
thing's word with an "s" stuck on, then a state that ends its clause, is the thing and "is"
(round 239: the speaker's own dead probe was taken for the one wanted). A plural said with its
verb ("my staplers are broken") and a word that is no thing of the office stay as said."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "sun")
_THINGS = frozenset({"stapler", "probe", "cable"})


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("my probes dead, need a thermometer", "my probe is dead, need a thermometer"),
        ("my staplers broken again", "my stapler is broken again"),
        ("the cables dead.", "the cable is dead."),
        ("my staplers are broken", "my staplers are broken"),  # a plural, with its verb
        ("my hands dead", "my hands dead"),  # no thing of the office
        ("my staplers broken spring", "my staplers broken spring"),  # the clause goes on
    ],
)
def test_unmarked_is(text: str, said: str) -> None:
    assert contracted_is(text, _THINGS)[0] == said


def test_the_own_broken_thing_is_not_the_one_wanted() -> None:
    frame = _frame("my staplers broken, can I borrow Wang's")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "sun")]
