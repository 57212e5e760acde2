"""A colleague's thing put away into the office's own disposal service by a verb that is no
errand ("chuck Morwen's drawing set in the recycling, it's rubbish anyway") is refused in
words, never noted as something told (blind round 43's class: "Noted. I did nothing.").
A colleague's thing the reader does read as the service is refused as before, a skip that is
no service of the office is declined as before, and one's own thing goes to the service."""

from __future__ import annotations

import pytest

from helpers.potting_shed import potting_shed
from helpers.reading import frame_reader

_frame = frame_reader(potting_shed, "ivo")


@pytest.mark.parametrize(
    "text",
    [
        "chuck Morwen's drawing set in the recycling, it's rubbish anyway",
        "chuck Morwen's drawing set in the recycling",
        "chuck Morwen's drawing set into the recycling bin, nobody looks at it",
        "chuck Morwen's drawings in the recycling",
        "put Morwen's drawings in the recycling bin",
        "toss Morwen's drawing set in the recycling",
        "chuck Morwen's trowel in the skip",
    ],
)
def test_a_colleagues_thing_put_away_is_refused(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame
    assert "Noted" not in frame.decline and "Sorry" in frame.decline, frame
    assert "morwen" not in frame.decline.replace("Morwen", ""), frame  # no internal id


@pytest.mark.parametrize(
    "text", ["put my drawing set in the recycling", "recycle my drawing set please"]
)
def test_ones_own_thing_goes_to_the_service(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [
        ("drawing", "ivo", "recycle")
    ], frame


def test_a_colleagues_thing_told_as_gone_is_no_request() -> None:
    frame = _frame("Morwen's drawing set went in the recycling")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "won't" not in frame.decline, frame
