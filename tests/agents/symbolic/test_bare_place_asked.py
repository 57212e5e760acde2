"""A send-out whose service needs an address (its ``destination_asked`` says so) to a bare
common noun ("courier my contract to the client", "to the factory", "post my letter to the
council", "to head office") asks where before anything moves: which one, at what address? A
name or an address ("Acme Ltd, 4 Mill Road, Leeds", "the factory in Leeds") is sent as said;
a non-answer to the question sends nothing."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.courier_room import raw_courier_room
from helpers.reading import answered_reader, frame_reader


def _raw_addressed() -> dict[str, Any]:
    """The courier room with its courier and a post service that both need an address."""
    raw = raw_courier_room()
    for op in raw["operations"]:
        if op["id"] == "courier":
            op["destination_asked"] = ob.ASKS_NAME_AND_ADDRESS
    raw["operations"].append(
        ob.operation(
            "post",
            "post",
            input="document",
            sends_out=True,
            destination_asked="the postal address",
        )
    )
    raw["facilities"].append(
        ob.facility("post_tray", "post tray", at="post_room", guards=["kit"], operations=["post"])
    )
    return raw


_addressed = ob.parsed(_raw_addressed)
_frame = frame_reader(_addressed, "ana")
_answered = answered_reader(_addressed, "ana")


@pytest.mark.parametrize(
    "text",
    [
        "can you courier my contract to the factory?",
        "courier my contract to the client",
        "courier my form to head office",
        "courier my invoice to the lab please",
        "post my letter to the council",
        "could you post my form to the main office",
    ],
)
def test_a_bare_kind_of_place_is_asked(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.decline is None, frame
    assert frame.question is not None and "address" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("courier my contract to Acme Ltd, 4 Mill Road, Leeds", "Acme Ltd, 4 Mill Road, Leeds"),
        ("courier my contract to the factory in Leeds", "the factory in Leeds"),
        ("post my letter to Leeds City Council", "Leeds City Council"),
    ],
)
def test_a_name_or_an_address_is_sent_as_said(text: str, where: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.destination for t in frame.tasks] == [where], frame


def test_a_non_answer_sends_nothing() -> None:
    frame = _answered(
        "courier my contract to the client", ["Sorry, I don't know more than I wrote."]
    )
    assert not frame.tasks and frame.question is not None, frame


def test_the_address_answered_is_where_it_goes() -> None:
    frame = _answered("courier my contract to the client", ["Acme Ltd, 4 Mill Road, Leeds"])
    assert frame.question is None, frame
    assert [t.destination for t in frame.tasks] == ["Acme Ltd, 4 Mill Road, Leeds"], frame


def test_a_service_that_needs_only_a_name_is_unchanged() -> None:
    # the courier room's own courier asks only for "the name of the place": as before
    frame = frame_reader(ob.parsed(raw_courier_room), "ana")("courier my form to the factory")
    assert [t.destination for t in frame.tasks] == ["the factory"], frame
