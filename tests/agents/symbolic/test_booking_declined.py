"""Booking a room or a slot: nothing in these offices books, so it is declined in words with
what can be done ("I can't book ..."), never noted as a statement. A participle after a
determiner describes a noun ("the recording studio", "a parking space") and an object after
the first word ("book me") is no subject, so the request is no clipped progressive
(``reading.clipped_progressive``). Booking a send-out's means for a thing ("book a courier for
my document") is that send-out where the office has one (``reading.booked_means``). A booking
told in the past ("I've booked the meeting room for 3") is a statement, as before."""

from __future__ import annotations

import functools

import pytest
from _offices import parser

from assistantx.agents.symbolic import InstructionParser
from helpers.courier_room import courier_room
from helpers.music_school import music_school


@functools.cache
def _courier() -> InstructionParser:
    return InstructionParser(courier_room())


def _declined(p: InstructionParser, text: str, requester: str) -> None:
    frame = p.parse(text, requester)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline_outcome == "unachievable", frame
    assert (frame.decline or "").startswith("Sorry, I can't "), frame


@pytest.mark.parametrize(
    "text",
    [
        "book me the recording studio for Thursday at 3",
        "book me a parking space for Monday",
        "could you reserve the recording studio for tomorrow morning",
        "book me the boardroom for Friday at 2",
    ],
)
def test_a_booking_is_declined_harbour(text: str) -> None:
    _declined(parser("harbour"), text, "may")


@pytest.mark.parametrize(
    "text",
    [
        "book me the meeting room for Friday at 2",
        "can you reserve the boardroom for tomorrow morning",
        "book me the printing room for Friday",
    ],
)
def test_a_booking_is_declined_default(text: str) -> None:
    _declined(parser("default"), text, "zhang")


def test_a_booking_of_a_room_with_a_facility_is_declined_music_school() -> None:
    _declined(InstructionParser(music_school()), "book me the recording studio for 3", "tom")


def test_a_booking_told_is_a_statement() -> None:
    # must not change: told in the past, nothing asked
    frame = parser("default").parse("I've booked the meeting room for 3", "zhang")
    assert frame.tasks == [] and frame.decline_outcome == "done", frame


def test_a_clipped_progressive_is_still_told() -> None:
    # must not change: a subject, then a participle under way
    frame = parser("harbour").parse("two parcels going out with Pat later", "may")
    assert frame.tasks == [] and frame.decline_outcome == "done", frame


def test_booking_a_courier_for_a_thing_is_the_send_out() -> None:
    frame = _courier().parse("can you book a courier for my document to Leeds", "kit")
    assert [(t.item, t.owner, t.operation, t.destination) for t in frame.tasks] == [
        ("document", "kit", "courier", "Leeds")
    ]
    asked = _courier().parse("book a courier for my document", "kit")
    assert asked.tasks == [] and asked.question is not None and "courier" in asked.question


def test_booking_a_means_the_office_lacks_is_declined() -> None:
    _declined(_courier(), "book a taxi for my document", "kit")
