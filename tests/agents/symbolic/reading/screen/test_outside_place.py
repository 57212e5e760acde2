"""A thing asked to go to someone's home or a street is declined in words (blind round 32's
wrong physical action: "drop Frank's drawings round to the applicant's house on Elm Road"
fetched the drawings from Frank); a place of the office, a colleague, and a send-out service's
destination are read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.dealership import dealership
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "liu")


@pytest.mark.parametrize(
    "text",
    [
        "can you drop Zhang's stapler round to the applicant's house on Elm Road",
        "bring my scissors to my house",
        "take my stapler over to 12 Mill Lane please",
    ],
)
def test_a_place_outside_is_declined_and_nothing_moves(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, I can't take things outside the office")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [("take my stapler to Zhang's desk", "zhang"), ("take my stapler to Zhang", "zhang")],
)
def test_the_offices_own_places_are_read_as_before(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame


def test_a_send_out_service_takes_its_destination() -> None:
    frame = frame_reader(dealership, "gary")("post my logbook to 4 Mill Lane")
    assert frame.decline is None, frame
