"""Approval said after a remark ("The new paint makes the drill bay look really sunny. Love
it.") is a reaction, answered in words: "Love it." was read as an order to do something with
"it" (the drill named before was fetched). A colleague's name used as an ordinary word in a
statement ("really sunny", "Olive oil's run out") is no one to ask about. "Love it" inside a
real request, or "I'd love it if you brought me ...", is still the request."""

from __future__ import annotations

import pytest

from helpers.design_studio import design_studio
from helpers.drill_shed import drill_shed
from helpers.reading import frame_reader

_shed = frame_reader(drill_shed, "nell")
_studio = frame_reader(design_studio, "nina")


@pytest.mark.parametrize(
    "text",
    [
        "The new paint makes the drill bay look really sunny. Love it.",
        "makes the drill bay look really sunny. Love it.",
        "The new light makes the drill bay look so bright. I absolutely love it!",
        "Love it.",
        "loving it so much",
        "I really like this.",
    ],
)
def test_approval_is_answered_in_words(text: str) -> None:
    frame = _shed(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "Glad you like it" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "Olive oil's run out in the kitchen again. And someone's had all the ginger biscuits.",
        "the walls look really olive",
    ],
)
def test_a_name_word_in_a_statement_is_a_word(text: str) -> None:
    frame = _studio(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    "text",
    [
        "I'd love it if you brought me the drill",
        "bring me the drill, love it",
        "I love this drill, bring it to me",
        "give the tape to Sunny",
    ],
)
def test_a_request_beside_approval_is_still_done(text: str) -> None:
    frame = _shed(text)
    assert frame.decline is None and len(frame.tasks) == 1, frame
