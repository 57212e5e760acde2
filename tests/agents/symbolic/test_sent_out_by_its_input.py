"""Sending a thing that only the office's send-out service takes to a place outside ("send my
parcel off to Coastline Deli on Mill Road") is that service, its destination as said, though
the service's own words are not said (blind round 65's class: declined as an errand outside
the office, or as a place outside it). A colleague after "to" is still a delivery; a thing
no send-out service takes, an errand to buy outside, and an office with no send-out service
are declined as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.estate_agency import estate_agency
from helpers.hostel import hostel
from helpers.reading import frame_reader

_frame = frame_reader(estate_agency, "nadia")
_hostel = frame_reader(hostel, "hamid")


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


_default_frame = frame_reader(_default, "mao")


def _assert_sent(text: str, item: str, operation: str, destination: str) -> None:
    """Nadia's ``item`` goes out by ``operation`` to ``destination``, asked nothing."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.operation, t.destination) for t in frame.tasks] == [
        (item, "nadia", operation, destination)
    ], frame


@pytest.mark.parametrize(
    ("text", "item", "operation", "destination"),
    [
        (
            "Send my parcel off to Coastline Deli on Mill Road",
            "parcel",
            "parcel_post",
            "Coastline Deli on Mill Road",
        ),
        (
            # the street after the comma is the place's too (fixer 84k, class 2: it was cut)
            "send my parcel to Coastline Deli, 4 Mill Road",
            "parcel",
            "parcel_post",
            "Coastline Deli, 4 Mill Road",
        ),
        (
            "please send this parcel to the Harbour Cafe on Quay Street",
            "parcel",
            "parcel_post",
            "the Harbour Cafe on Quay Street",
        ),
        (
            "send my contract off to Harrow Homes on Kiln Lane",
            "document",
            "courier",
            "Harrow Homes on Kiln Lane",
        ),
    ],
)
def test_its_input_sent_outside_is_the_send_out_service(
    text: str, item: str, operation: str, destination: str
) -> None:
    _assert_sent(text, item, operation, destination)


def test_on_an_office_whose_service_has_no_word_of_sending() -> None:
    frame = _hostel("Send my parcel off to Coastline Deli on Mill Road")
    assert frame.decline is None, frame
    assert [(t.item, t.operation) for t in frame.tasks] == [("parcel", "courier")], frame


def test_to_a_colleague_it_is_still_a_delivery() -> None:
    frame = _frame("send my parcel to Owen")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "parcel", "owen")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "send my stapler to the deli on Mill Road",
        "pick me up a sandwich from the deli on Mill Road",
    ],
)
def test_what_no_service_sends_is_declined_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame


def test_an_office_with_no_send_out_service_declines_as_before() -> None:
    frame = _default_frame("send my document off to Coastline Deli on Mill Road")
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("text", "item", "operation", "destination"),
    [
        (
            "this form needs to go by courier to Harrow Homes, 3 Kiln Lane",
            "document",
            "courier",
            "Harrow Homes, 3 Kiln Lane",
        ),
        (
            "this form needs to go by courier to the agent, Harrow Homes, 3 Kiln Lane",
            "document",
            "courier",
            "the agent, Harrow Homes, 3 Kiln Lane",
        ),
        (
            "these forms should go by courier to Harrow Homes, 3 Kiln Lane",
            "document",
            "courier",
            "Harrow Homes, 3 Kiln Lane",
        ),
        (
            "this parcel has to go by post to Coastline Deli on Mill Road",
            "parcel",
            "parcel_post",
            "Coastline Deli on Mill Road",
        ),
    ],
)
def test_a_thing_that_has_to_go_by_the_services_means_is_sent(
    text: str, item: str, operation: str, destination: str
) -> None:
    _assert_sent(text, item, operation, destination)


def test_a_role_then_its_holders_name_is_one_destination() -> None:
    frame = _frame("courier my contract to the buyer, Ms Ada Kerr, 12 Elm Road")
    assert [t.destination for t in frame.tasks] == ["the buyer, Ms Ada Kerr, 12 Elm Road"], frame


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("courier my contract to the Leeds agent, it has to go today", "the Leeds agent"),
        ("courier my contract to the lab, the Bristol one", "the Bristol lab"),
    ],
)
def test_a_comma_after_a_role_with_no_name_ends_it_as_before(text: str, destination: str) -> None:
    frame = _frame(text)
    assert [t.destination for t in frame.tasks] == [destination], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [("my form needs to go to Owen", "owen"), ("this form has to go to Owen", "owen")],
)
def test_a_thing_that_has_to_go_to_a_colleague_is_still_delivered(
    text: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", recipient)], frame


@pytest.mark.parametrize(
    "text",
    [
        "Send my parcel off to the Harbour Cafe on Quay Street, and bring me Owen's stapler",
        "bring me Owen's stapler and send my parcel off to the Harbour Cafe on Quay Street",
    ],
)
def test_a_thing_sent_out_beside_another_request_is_still_sent(text: str) -> None:
    """The other request's thing (a stapler no send-out service takes) does not make the
    sending an errand outside: the thing sent is the one named after the sending verb."""
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert sorted((t.item, t.operation, t.destination) for t in frame.tasks) == [
        ("parcel", "parcel_post", "the Harbour Cafe on Quay Street"),
        ("stapler", None, None),
    ], frame


def test_another_thing_sent_outside_is_declined_as_before() -> None:
    frame = _frame("send my stapler off to the Harbour Cafe on Quay Street")
    assert frame.tasks == [] and frame.decline is not None, frame
