"""A correction of whose thing said with no pause before its words ("bring me Wang's stapler
no wait Zhang's"): the corrected owner replaces the first, and the correction's words are
never left behind as a withdrawal of the corrected request; a reason after it that names the
replaced owner again ("..., wang's is broken") is context, never a second request nor an undo
(fix201b class 1: before, the request was dropped, or Wang's stapler was brought)."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        # the class's own shape
        "bring me Wang's stapler no wait Zhang's, wang's is broken",
        "bring me Wang's stapler no wait Zhang's",
        "bring me Wang's stapler oh wait no Zhang's, Wang's is away",
        "bring me Wang's stapler no wait Zhang's - Wang's is in for repair",
        # must not change: the correction said with its pauses, and the other markers
        "bring me Wang's stapler, no wait, Zhang's, wang's is broken",
        "bring me Wang's stapler sorry Zhang's",
        "bring me Wang's stapler, I mean Zhang's, wang's is broken",
    ],
)
def test_the_corrected_owner_replaces_the_first(text: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "lee")
    ], frame


@pytest.mark.parametrize(
    "text", ["bring me Wang's stapler no wait", "bring me Wang's stapler. no wait, never mind"]
)
def test_a_withdrawal_without_a_new_owner_still_withdraws(text: str) -> None:
    frame = _lee(text)
    assert frame.tasks == [] and frame.decline is not None, frame
