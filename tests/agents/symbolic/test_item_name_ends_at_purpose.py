"""An item asked for with its purpose after "to" ("I need a pen to mark the boxes"): the
thing's name ends before "to", so an office without one declines "no pen", never "no pen to
mark" (fix103h, class 2's analogue; ``screen.terms.Terms.unknown_thing``). Before, the words
up to the next determiner were read as the thing's name."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


def _declined(office: str, text: str, requester: str) -> str:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [], frame
    return frame.decline or ""


@pytest.mark.parametrize(
    ("office", "text", "requester", "thing"),
    [
        ("harbour", "I need a pen to mark the boxes", "rose", "pen"),
        ("harbour", "I need a stapler to staple the handouts", "will", "stapler"),
        ("harbour", "could you bring me a glue stick to fix the labels", "rose", "glue stick"),
        ("default", "I need a ruler to draw the lines", "lee", "ruler"),
    ],
)
def test_the_declined_thing_is_named_without_its_purpose(
    office: str, text: str, requester: str, thing: str
) -> None:
    said = _declined(office, text, requester)
    assert f"there is no {thing} in this office" in said, said


# -- must not change: an office that has the thing gives it; no purpose, same name ----------
def test_an_office_with_the_thing_gives_it_whatever_its_purpose() -> None:
    assert tasks_of("default", "I need a pen to mark the boxes", "lee") == [
        ("transfer", "pen", None, "lee")
    ]


def test_a_thing_asked_for_without_a_purpose_is_named_as_before() -> None:
    said = _declined("harbour", "I need a glue stick", "rose")
    assert "there is no glue stick in this office" in said, said
