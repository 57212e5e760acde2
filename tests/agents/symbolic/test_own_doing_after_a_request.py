"""A clause of the speaker's own doing after a request ("need to / have to / gotta <verb> ...",
no request of its own aimed at the assistant) is the request's reason, even where it names an
item word: "yo can u grab bjorns laser, need to check levels on L2" answered "not sure what to
do with levels" (the place "on L2" read as a placement before the doing), and "grab me a pen,
gotta sign the contracts" asked what to do with the pen (a colleague's work, "sign", said as
the speaker's own, read as asked of the robot). A need of a thing of its own and an errand or
a service asked are read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader
from helpers.site_cabin import site_cabin

_WHO = {default_office: "lee", harbour_office: "will", site_cabin: "tamsin"}


def _tasks(office: OfficeOf, text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = frame_reader(office, _WHO[office])(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "item", "owner"),
    [
        # the class's analogue: the laser level said "laser", the reason says "levels"
        (
            site_cabin,
            "yo can u grab bjorns laser, need to check levels on L2",
            "laser_level",
            "bjorn",
        ),
        (
            site_cabin,
            "can you grab Bjorn's level, gotta check the levels on the slab",
            "laser_level",
            "bjorn",
        ),
        (
            site_cabin,
            "bring me kofi's tape measure, have to measure the window on level 3",
            "tape_measure",
            "kofi",
        ),
        # default office: works today, kept
        (
            default_office,
            "can u grab wangs stapler, need to staple the forms for the review",
            "stapler",
            "wang",
        ),
        # a colleague's work said as the speaker's own
        (default_office, "grab me a pen, gotta sign the contracts", "pen", None),
        (default_office, "grab me a pen, I need to sign the contracts", "pen", None),
        (
            harbour_office,
            "bring me a highlighter, need to mark up the minutes",
            "highlighter",
            None,
        ),
        (
            harbour_office,
            "can you grab Rose's tape, gotta wrap the parcels on my desk",
            "tape",
            "rose",
        ),
    ],
)
def test_the_speakers_own_doing_is_the_reason(
    office: OfficeOf, text: str, item: str, owner: str | None
) -> None:
    assert _tasks(office, text) == [("transfer", item, owner, _WHO[office])]


def test_a_thing_of_its_own_is_a_second_part() -> None:
    tasks = _tasks(default_office, "grab me a pen, and I need the stapler too")
    assert tasks == [("transfer", "pen", None, "lee"), ("transfer", "stapler", None, "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "grab me a pen, need to get my report printed",  # an errand's verb: asked
        "grab me a pen, need you to print my report",  # asked of the robot
    ],
)
def test_work_asked_of_the_robot_is_still_asked(text: str) -> None:
    assert ("print", "file", "lee", "lee") in _tasks(default_office, text)
