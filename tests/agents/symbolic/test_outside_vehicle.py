"""A thing told to go into a vehicle or a home ("put Wang's stapler in my car", "leave the
scissors in Wang's van") is declined in words: the robot never leaves the office (or asked
what to do, where the ``unplaced`` rule read it first). It was
answered "Noted" (as if told), or the scissors were fetched for the requester. A place of the
office ("on my desk") is still a delivery, and the speaker's own doing is still told."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "sun")
_harbour = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("office", "text", "owner"),
    [
        ("default", "put Wang's stapler in my car", "Wang Fang"),
        ("default", "put my book in my car", ""),
        ("default", "leave the scissors in Wang's van", ""),
        ("default", "take my book to my car", ""),
        ("default", "pop it in the boot", ""),
        ("default", "can you put my book in my car?", ""),
        ("harbour", "put Grace's ruler in my car", "Grace Huang"),
        ("harbour", "leave the umbrella in the van", ""),
        ("harbour", "drop the calculator into Will's truck", ""),
    ],
)
def test_a_thing_put_in_a_vehicle_is_declined(office: str, text: str, owner: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.tasks == [], frame
    if frame.question is not None:  # "leave the umbrella in the van": asked what to do
        assert "not sure what to do" in frame.question, frame
        return
    assert frame.decline is not None and "outside the office" in frame.decline, frame
    assert "Noted" not in frame.decline, frame
    if owner:  # a colleague's thing: their yes would be needed anyway
        assert f"{owner}'s" in frame.decline and "yes" in frame.decline, frame


@pytest.mark.parametrize(
    ("office", "text", "owner"),
    [
        ("default", "put Wang's stapler on my desk", "wang"),
        ("harbour", "put Grace's ruler on my desk", "grace"),
    ],
)
def test_a_thing_put_in_the_office_is_delivered(office: str, text: str, owner: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert [(t.kind, t.owner) for t in frame.tasks] == [("transfer", owner)], frame


def test_the_speakers_own_doing_is_told() -> None:
    frame = _default("I put my book in my car")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "outside the office" not in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        # round 231: where a lack is, said with "we're" (a verb of being), is no placement;
        # the request after it asks for a bag of what ran out
        ("we're out of paper in the van, can you grab a pack from the supply room", "paper"),
        ("we're out of paper on the van, can you bring me some", "paper"),
    ],
)
def test_where_a_lack_is_is_no_placement(text: str, item: str) -> None:
    frame = _default(text)
    assert frame.decline is None or "outside the office" not in frame.decline, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "sun")], frame
