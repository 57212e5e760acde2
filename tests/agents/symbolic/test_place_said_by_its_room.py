"""A place said by the kind of room its name opens with ("the café" for "Café counter" and
"Café kitchen", "the post room" for "Post room counter") is the office's own
(``clipped_names.place_openers``): a town's shop named so ("from the café") was read as an
errand outside the office and declined, though the office makes the shake there (blind round
256). Said with a phrase that places it outside ("the café round the corner"), or a shop the
office has no room of, it is still declined or asked about as before."""

from __future__ import annotations

import pytest
from _cafe_office import read_as_ana


@pytest.mark.parametrize(
    "text",
    [
        "could you get me a protein shake from the café",
        "could you get me a protein shake from the cafe",
        "get me a smoothie from the Café please",
    ],
)
def test_the_shake_is_made_in_the_offices_cafe(text: str) -> None:
    frame = read_as_ana(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "shake", "ana")]


def test_the_room_opening_one_place_name_is_that_place() -> None:
    frame = read_as_ana("take my watch to the post room")
    assert frame.question is not None and "Ben Hart is there" in frame.question, frame


@pytest.mark.parametrize(
    "text",
    [
        "a coffee from the kitchen please",  # "Kitchen counter": already the office's
        "bring me a stapler from the post room",
    ],
)
def test_neighbours_still_read_inside(text: str) -> None:
    frame = read_as_ana(text)
    assert frame.decline is None and frame.question is None, frame
    assert len(frame.tasks) == 1


@pytest.mark.parametrize(
    "text",
    [
        "could you get me a coffee from the café round the corner",
        "could you get me a coffee from the cafe across the street",
        "could you get me a sandwich from the deli",
    ],
)
def test_a_cafe_outside_is_still_declined(text: str) -> None:
    frame = read_as_ana(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "outside the office" in frame.decline


def test_a_shop_by_its_own_name_is_never_made_here() -> None:
    frame = read_as_ana("could you get me a coffee from Costa")
    assert frame.tasks == [], frame


@pytest.mark.parametrize(
    "text",
    [
        "my watch needs polishing before it comes into the post room",
        "polish my watch before it comes into the café",
    ],
)
def test_a_room_in_a_clause_of_time_is_when_not_where(text: str) -> None:
    """ "... before it comes into the post room": where the thing goes afterwards, never a
    room the request takes it to (``event_clause.in_time_clause``); read as the room, who
    there should get it was asked, and the polish was never run."""
    frame = read_as_ana(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.recipient) for t in frame.tasks] == [("polish", "watch", "ana")]


def test_a_room_the_request_takes_it_to_still_asks_who_there() -> None:
    frame = read_as_ana("polish my watch and take it into the post room")
    assert frame.question is not None and "Ben Hart is there" in frame.question, frame
