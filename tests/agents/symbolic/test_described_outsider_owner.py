"""Fixer fix180c class 4: "I need tape for a new starter's badge" asked "I don't know anyone
called 'starter'". A lower-case common noun's possessive after a determiner and a word or two
that describe the person ("a new starter's", "our external contractor's") names an outsider,
as "the visitor's" does (``outsider_owner.described_before``), and the thing of the "for"
phrase is what the thing asked for is for (``_objects._modifier_phrase``), never a second
thing to fetch: the thing asked for comes to the speaker."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader
from helpers.swab_clinic import swab_clinic

_harbour = frame_reader(harbour_office, "will")
_clinic = frame_reader(swab_clinic, "ines")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need tape for a new starter's badge", "tape"),
        ("can I get a ruler for our external contractor's badge", "ruler"),
        ("bring me a calculator for the new intern's form", "calculator"),
        # must not change: the determiner right before the owner, or a colleague's
        ("I need tape for a starter's badge", "tape"),
        ("I need tape for the visitor's badge", "tape"),
        ("I need tape for Sue's badge", "tape"),
    ],
)
def test_harbour_the_thing_for_an_outsiders_thing_is_the_speakers(text: str, item: str) -> None:
    frame = _harbour(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "will")
    ], frame


def test_clinic_a_stapler_for_a_new_starters_form() -> None:
    frame = _clinic("get me a stapler for a new starter's form")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "ines")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a capitalised name nobody has is still asked about
        "I need tape for a new Starter's badge",
        "I need tape for Bob's badge",
    ],
)
def test_a_name_nobody_has_is_still_asked(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and "know anyone called" in (frame.question or ""), frame
