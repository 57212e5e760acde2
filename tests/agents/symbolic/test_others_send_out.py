"""A colleague's thing said to need one of the office's send-out services ("Dev's contract
needs couriering to Leeds", "Pat's letter needs to be posted"), with no request wording: the
thing would leave the office on someone else's word, so it is asked about ("Shall I courier
it to Leeds?"), never sent. The speaker's own thing is sent as before, and a colleague's
thing that needs work done in the office ("Dev's contract needs printing") is read as
before."""

from __future__ import annotations

import functools

import pytest

from helpers.chambers_post import chambers_post
from helpers.courier_room import courier_room
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.reading import frame_reader

_courier_room = frame_reader(courier_room, "ana")
_chambers = frame_reader(chambers_post, "nadia")
_harbour = frame_reader(harbour_that_posts, "may")
_default = frame_reader(
    functools.partial(
        default_office_that_sends_out, "courier", "send by courier", "courier", "the address"
    ),
    "chen",
)


@pytest.mark.parametrize(
    ("read", "text", "shall"),
    [
        (_courier_room, "Dev's contract needs couriering to Leeds", "Shall I courier it to Leeds?"),
        (
            _courier_room,
            "Kit's signed statement needs couriering to Leeds City Council, 3 Kiln Lane",
            "Shall I courier it to Leeds City Council, 3 Kiln Lane?",
        ),
        (_chambers, "Owen's letter needs posting to Hull", "Shall I post it to Hull?"),
        (_harbour, "Pat's letter needs to be posted to Hull", "Shall I post it to Hull?"),
        (_harbour, "Pat's letter needs franking", "Shall I frank it?"),
        (
            _default,
            "Zhang's signed contract needs couriering to Hull",
            "Shall I courier it to Hull?",
        ),
    ],
)
def test_a_colleagues_thing_is_asked_about_never_sent(read: object, text: str, shall: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.endswith(shall), frame.question


# -- must not change ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("read", "text", "owner"),
    [
        (_courier_room, "my contract needs couriering to Leeds", "ana"),
        (_chambers, "my letter needs posting to Hull", "nadia"),
        (_harbour, "my letter needs posting to Hull", "may"),
    ],
)
def test_the_speakers_own_thing_is_sent(read: object, text: str, owner: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.question is None and frame.decline is None, frame
    assert [(t.owner, t.destination) for t in frame.tasks] == [
        (owner, "Leeds" if owner == "ana" else "Hull")
    ]


def test_a_colleagues_thing_that_needs_office_work_reads_as_before() -> None:
    frame = _courier_room("Dev's contract needs printing")
    assert [(t.kind, t.owner) for t in frame.tasks] == [("copy", "dev")]


def test_a_request_to_send_a_colleagues_thing_is_a_request() -> None:
    frame = _courier_room("courier Dev's contract to Leeds")
    assert [(t.owner, t.operation, t.destination) for t in frame.tasks] == [
        ("dev", "courier", "Leeds")
    ]
