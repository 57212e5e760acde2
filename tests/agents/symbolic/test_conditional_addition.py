"""One more thing added after a request with a condition on whether it can be had ("and a tea
if the kettle's on", "a tea too if it's no trouble") is asked for too (blind round 60's
class: only the first thing came); the condition is about availability, which the errand
finds out. A condition with no thing of its own keeps its reading."""

from __future__ import annotations

import pytest

from helpers.edit_suite import edit_suite
from helpers.reading import frame_reader

_frame = frame_reader(edit_suite, "nadia")


@pytest.mark.parametrize(
    "text",
    [
        "heading out to the yard. could you bring me a hard hat? and a tea if the kettle's on. "
        "thanks!",
        "bring me a hard hat. a tea too if it's no trouble",
        "bring me a hard hat please, and a tea if the kettle is on",
        "bring me a hard hat? oh and a tea if the kettle's boiled",
        "could you grab me a hard hat? a tea as well if you can",
        "bring me a hard hat and a tea if there's any",
    ],
)
def test_the_conditional_thing_is_asked_for_too(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "hard_hat", "nadia"),
        ("produce", "tea", "nadia"),
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a hard hat. the tea is ready if the kettle's on",
        "bring me a hard hat. Sam makes a tea if the kettle's on",
    ],
)
def test_a_told_condition_adds_nothing(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "hard_hat")], frame
