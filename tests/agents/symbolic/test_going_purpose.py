"""A place after an infinitive of going is the reason for the thing, not where it goes
(``screen.outside_place``): "who's got the umbrella? I need it to get to the Marsh Lane
site" asks for the umbrella, as "I need it to write a letter" would; the street is where the
speaker goes. A thing to be taken to a street ("take my umbrella to 12 Mill Lane", "I need
you to take it to ...": the verb has the thing as its object) is still declined in words.
On the dataset's harbour and default offices."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "pat")
_default = frame_reader(default_office, "lin")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        # the class's analogues
        ("harbour", "who's got the umbrella? I need it to get to the Marsh Lane loss", "umbrella"),
        ("harbour", "I need an umbrella to get to the station", "umbrella"),
        # variants of our own: other verbs of going, particles, things, offices
        ("harbour", "who has a calculator? I need it to drive to the Marsh Lane job", "calculator"),
        (
            "harbour",
            "can I borrow Rose's umbrella? I need it to walk down to Kings Road",
            "umbrella",
        ),
        (
            "default",
            "can I borrow Wang's stapler? I need it to get to the Mill Lane site",
            "stapler",
        ),
        ("default", "I need scissors to head down to the Elm Road site", "scissors"),
    ],
)
def test_a_place_gone_to_for_a_reason_leaves_the_request(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert frame.decline is None, frame.decline
    assert [t.item for t in frame.tasks] == [item], frame.tasks


@pytest.mark.parametrize(
    ("office", "text"),
    [
        # must not change: the thing itself is taken to the street
        ("harbour", "take my umbrella to 12 Mill Lane"),
        ("harbour", "I need you to take my umbrella to 12 Mill Lane"),
        ("default", "could you bring my stapler round to 4 Elm Drive"),
    ],
)
def test_a_thing_taken_to_a_street_is_still_declined(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame.tasks
    assert frame.decline is not None, frame.question
