"""A preface that announces a question ("frank question:", "quick q -", "honest question,")
names nobody and asks nothing (fixer 59g class 2; ``reading.question_preface``): what follows
is read as if said alone, so "who's got a stapler I could use tomorrow?" is a question about a
later need, answered in words and offered for then, never a stapler fetched now. Read as said,
"frank" was a colleague called Frank and the question a request made now. Frank addressed
("Frank, who's got a stapler?"), Frank's own thing, and a question for now keep their
readings."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


def _office_with_frank() -> Office:
    """The default office with Dang Hao called Frank Dang: "frank" is a colleague's name."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    for p in raw["people"]:
        if p["id"] == "dang":
            p["name"] = "Frank Dang"
    return parse_office(raw)


_frank = frame_reader(_office_with_frank, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "frank question: who's got a stapler I could use tomorrow?",
        "Frank question - anyone got a stapler I could borrow next week?",
        "quick q - anyone have a stapler i could borrow next week?",
        "honest question, anyone got a stapler I could borrow next week?",
        "hey, random q: anyone got a stapler I could borrow tomorrow?",
    ],
)
def test_a_question_for_later_after_a_preface_is_answered_not_fetched(text: str) -> None:
    frame = _frank(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and "have a stapler" in frame.decline, frame


def test_a_question_for_now_is_offered_as_before() -> None:  # must not change
    frame = _frank("who's got a stapler I could use now?")
    assert not frame.tasks and frame.question is not None and "Shall I" in frame.question


def test_a_preface_before_a_question_for_now_offers_it() -> None:
    frame = _frank("quick question: who's got a stapler?")
    assert not frame.tasks and frame.question is not None and "Shall I" in frame.question


def test_frank_addressed_keeps_its_reading() -> None:  # must not change
    frame = _frank("Frank, who's got a stapler?")
    assert not frame.tasks and frame.question is not None and "Shall I" in frame.question


def test_franks_thing_is_his() -> None:  # must not change
    frame = _frank("frank's stapler please")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "dang", "lee")]
