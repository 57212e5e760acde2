"""Blind rounds 43-48, class J1: a send-out service's destination said as a proper name of a
place outside the office after "to" or "at", even where the service's own verb is not said
("my vials go out to Kessler Labs", "send my papers to Ironbridge Records Store") or a word
of the name is a colleague's surname ("Sam *Records*"): the place is the destination, never
someone to look up (``send_off.sent_off``, ``destination.find_outside``; on
``helpers.county_court``; the rounds' own offices and sentences were never read). A
colleague's name after "to" stays the colleague, and a person going out sends nothing."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.county_court import county_court
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(county_court, "tess")
_answered = answered_reader(county_court, "tess")


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.item, t.operation, t.destination) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        (
            "could my cryovials go out on dry ice to Kessler Labs in Basel today?",
            ("cryovial", "ship", "Kessler Labs in Basel"),
        ),
        ("my cryovials need to go out to Halberg Biotech", ("cryovial", "ship", "Halberg Biotech")),
        ("can my cryovials go off to Kessel Labs tomorrow", ("cryovial", "ship", "Kessel Labs")),
        (
            "send my case papers to Ironbridge Records Store",
            ("case_papers", "archive", "Ironbridge Records Store"),
        ),
        (
            "Please send my closed case papers to the off-site archive at Ironbridge Records "
            "Store.",
            ("case_papers", "archive", "Ironbridge Records Store"),
        ),
        (
            "please archive my case papers at Ironbridge Records Store",
            ("case_papers", "archive", "Ironbridge Records Store"),
        ),
        (
            "could you send my case file to the Fenwick Street Depository",
            ("case_papers", "archive", "the Fenwick Street Depository"),
        ),
    ],
)
def test_a_named_place_outside_is_the_destination(text: str, sent: tuple[str, str, str]) -> None:
    frame = _frame(text)
    assert _sent(frame) == [sent], frame.question


@pytest.mark.parametrize(
    "text",
    ["send my case papers to Nia", "send my case papers to Nia Kessel", "send Omar my case file"],
)
def test_a_colleague_after_to_is_still_the_colleague(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.operation) for t in frame.tasks] == [("case_papers", None)]


@pytest.mark.parametrize(
    "text",
    [
        "I'm going out to Kessler Labs, can you bring me my cryovials",
        "archive my case papers",
        "archive my case papers at 3pm",
    ],
)
def test_no_place_named_sends_nothing_out(text: str) -> None:
    assert not any(t.destination for t in _frame(text).tasks)


def test_the_answered_place_is_the_destination() -> None:
    frame = _answered("archive my case papers", ["Ironbridge Records Store"])
    assert _sent(frame) == [("case_papers", "archive", "Ironbridge Records Store")]
