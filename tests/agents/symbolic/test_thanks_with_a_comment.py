"""Thanks for work done with a comment after it (round 201's class): "thanks for sorting the
heating yesterday, lovely and warm now" is words; the comment's "warm", paired by "and" with an
adjective, says how the place is, never the office's heating service asked for (on main:
"Which item do you mean for me to heat?"). The verb itself still asks."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "thanks for sorting the heating yesterday, lovely and warm now",
        "cheers for fixing the heater earlier, nice and warm now",
        "thanks for fixing the printer earlier, working great now",
        "cheers for sorting the light yesterday, nice and bright now",
    ],
)
def test_thanks_with_a_comment_is_words(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "welcome" in frame.decline, frame


@pytest.mark.parametrize(
    "text", ["thanks for the lunch, could you warm it up", "thanks, warm my lunch please"]
)
def test_thanks_then_the_service_still_asks_it(text: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "lunch")], frame
