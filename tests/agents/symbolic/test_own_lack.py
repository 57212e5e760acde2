"""A lack of the speaker's own that asks nothing: said of home ("run out of pens at home
haha"), or beside the speaker's own plan to get more ("I'll grab some on my way back"), with no
request in the message, is answered in words (blind round 40's class: a pen was fetched from
a colleague). A lack with a request ("out of pens, can you bring me one?") still delivers,
and "run out and buy me some pens" is still an errand outside the office."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.roof_garden import roof_garden

_frame = frame_reader(roof_garden, "rosa")


@pytest.mark.parametrize(
    "text",
    [
        "run out of pens at home haha, I'll grab some on my way back",
        "ran out of pens at home, I'll grab some on my way back",
        "out of pens at home lol, will buy some later",
        "no pens left at home, I'll get some on the way back",
        "I've run out of pens at home, I'll pick some up tonight",
        "we're out of pens back at the flat",
        "out of pens, I'll grab some from the cupboard later",
    ],
)
def test_an_own_lack_that_asks_nothing_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    "text",
    [
        "out of pens, can you bring me one?",
        "run out of pens, can you bring me one?",
        "run out of pens at home, could you bring me one?",
        "no pens left, bring me one",
        "out of pens",
    ],
)
def test_a_lack_with_a_request_still_delivers(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "pen", "rosa")]


def test_running_out_to_buy_is_still_an_errand_outside() -> None:
    frame = _frame("run out and buy me some pens")
    assert frame.tasks == [] and frame.decline is not None and "outside" in frame.decline
