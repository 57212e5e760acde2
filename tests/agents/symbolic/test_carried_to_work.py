"""Carrying a thing to the place of a facility and having that facility's work done on "it"
("take my document down to the copy room and have it digitised") is that work on the thing,
its result back to the speaker (blind round 63's class: two tasks that each only handed the
thing back, so nothing was done). A colleague said to expect it is context, not the
recipient; a thing taken to a person in that room is a delivery, as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_frame = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "could you take my document down to the copy room and have it digitised? "
        "Faith knows it's coming",
        "take my document to the copy room and have it scanned",
        "take my document to the copy room and get it scanned please",
        "bring my document to the copy room and have it digitized, Mark is expecting it",
    ],
)
def test_the_work_at_the_place_carried_to_is_done(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.facility) for t in frame.tasks] == [
        ("copy", "document", "may", "may", "scanner")
    ], frame


def test_a_thing_taken_to_a_person_in_that_room_is_delivered() -> None:
    frame = _frame("take my document down to Faith in the copy room")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", "faith")
    ], frame


def test_the_rooms_one_service_on_the_thing_is_done() -> None:
    # the copy room's scanner is its one service on documents (``reading.room_service``):
    # before, who in the room should get the document was asked
    frame = _frame("take my document to the copy room")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", "may", "may")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        # the place named has no facility for the work: the old reading, which asks
        "take my document to the kitchen and have it scanned",
    ],
)
def test_without_the_works_place_it_is_read_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.question is not None and not frame.tasks, frame
