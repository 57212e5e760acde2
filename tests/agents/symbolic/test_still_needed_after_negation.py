"""A negated service on the speaker's own thing, with why ("don't shred my document, I still
need it for the 5:30 meeting", "please don't copy my contract yet, I still need to edit it"),
is a wish answered in words: the negation is read for a verb that destroys too ("shred",
"throw away") whether the office has the machine or not, and the speaker's need of the thing
said before, or of their own doing, is its reason (``screen.still_needed``). Before, both
asked "Who should get your document?". A request after the negation, or a need of a thing of
its own, is read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "wang")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "don't shred my document, I still need it for the 5:30 meeting",
        "please don't copy my contract yet, I still need to edit it",
        "don't shred my document",
        "do not throw away my document, I still need it",
        "don't shred those, we still need them until Friday",
        "don't bring me coffee, I still need to finish my water",
    ],
)
def test_default_nothing_moves_and_it_is_said(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("OK, I won't")


@pytest.mark.parametrize(
    "text",
    [
        "don't scan my contract, I still need it for the meeting",
        "please don't laminate my badge yet, I still need to fix the photo",
        "don't print my file, I still need to edit it",
    ],
)
def test_harbour_nothing_moves_and_it_is_said(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("OK, I won't")


def test_a_request_after_the_negation_is_read() -> None:
    """Neighbour: "..., bring it to Zhang instead" asks for the hand-over."""
    frame = _DEFAULT("don't shred my document, bring it to Zhang instead")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", "zhang")
    ]


def test_a_need_of_another_thing_is_a_request() -> None:
    """Neighbour: "I need a water instead" names a thing of its own, asked for."""
    frame = _DEFAULT("don't bring me coffee, I need a water instead")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "water")]


def test_a_need_of_work_on_it_is_a_request() -> None:
    """Neighbour: "I need it scanned by Mark" asks for the work, not a reason."""
    frame = _HARBOUR("don't scan my contract now, I need it scanned by Mark")
    assert frame.tasks or frame.question is not None, frame
    assert frame.decline is None
