"""A reason fragment after a request ("need the laundry numbers", "for the laminator",
"it's for the laminator rota") names a service only as its topic: the request is done as
asked, and no service is asked for on its thing (round 166, class 3;
``screen.service_word_reason``). A fragment with a thing and a service's participle of its
own, and a request whose thing the service works on, keep their readings."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_kit = frame_reader(kit_room, "ana")
_SAMS = ("send_file", "spreadsheet", "sam", "ana", None)


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue
        "could you get me Sam's spreadsheet? need the laundry numbers",
        # variants: "for", "it's for", another facility, a service's verb as the topic
        "can you get me Sam's spreadsheet? for the laundry",
        "could you send me Sam's spreadsheet? it's for the laminator rota",
        "could you get me Sam's spreadsheet? just need the laminator totals",
        "could you send me Sam's spreadsheet? need the wash figures",
    ],
)
def test_a_service_in_the_reason_is_no_request(text: str) -> None:
    frame = _kit(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [_SAMS], (
        frame
    )


@pytest.mark.parametrize(
    ("office", "requester", "text", "owner"),
    [
        ("harbour", "may", "can you get me Mark's file? for the laminator", "mark"),
        ("harbour", "may", "could you send me Mark's file? need the scanner figures", "mark"),
        ("default", "lee", "could you send me Mao's file? for the microwave", "mao"),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, owner: str
) -> None:
    assert tasks_of(office, text, requester) == [("send_file", "file", owner, requester)]


def test_a_second_request_with_its_own_thing_is_kept() -> None:
    frame = _kit("could you get me Sam's spreadsheet? need my costume washed")
    assert [(t.item, t.operation) for t in frame.tasks] == [
        ("spreadsheet", None),
        ("costume", "wash"),
    ], frame


def test_the_service_of_the_thing_asked_is_where_it_goes() -> None:
    # the costume is what the laundry washes: "for the laundry" asks for the washing
    frame = _kit("take my costume please, for the laundry")
    assert [(t.item, t.operation) for t in frame.tasks] == [("costume", "wash")], frame
