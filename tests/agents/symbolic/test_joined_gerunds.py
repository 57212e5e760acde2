"""A second request joined by "and" to a "would you mind <verb>-ing" one is said in -ing too:
"would you mind taking my badge to be laminated, and getting my timesheet signed by Mark?"
asks both. A clause with its own subject, or a gerund describing a noun ("packing tape"), is
no second request."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.joined_gerunds import joined_gerunds
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "mao")
_HARBOUR = frame_reader(harbour_office, "bill")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Would you mind taking my badge to be laminated, and getting my timesheet signed by Mark?",
        "would you mind laminating my badge, and getting my timesheet signed by Mark?",
        "would you mind taking my badge to be laminated and then getting my letter signed by Mark?",
    ],
)
def test_harbour_two_gerund_requests(text: str) -> None:
    frame = _HARBOUR(text)
    assert _tasks(frame) == [("heat", "badge", "bill"), ("sign", "document", "bill")], frame


def test_harbour_a_joined_taking_is_its_own_errand() -> None:
    frame = _HARBOUR("would you mind bringing me a ruler and then taking my timesheet to Mark?")
    assert _tasks(frame) == [("transfer", "ruler", "bill"), ("transfer", "document", "mark")]


@pytest.mark.parametrize(
    ("text", "first"),
    [
        ("would you mind photocopying my contract, and getting my form signed by Zhang?", "copy"),
        ("would you mind copying my report and having my invoice signed by Zhang?", "copy"),
    ],
)
def test_default_office_two_gerund_requests(text: str, first: str) -> None:
    frame = _DEFAULT(text)
    assert _tasks(frame) == [(first, "document", "mao"), ("sign", "document", "mao")], frame


def test_default_office_a_fetch_and_a_copy() -> None:
    frame = _DEFAULT("would you mind bringing me a pen and having my report copied?")
    assert _tasks(frame) == [("transfer", "pen", "mao"), ("copy", "document", "mao")], frame


def test_a_clause_of_its_own_adds_no_request() -> None:
    text = "would you mind bringing me a ruler, I'm measuring and cutting the paper"
    assert joined_gerunds(text) == text
    assert _tasks(_HARBOUR(text)) == [("transfer", "ruler", "bill")]


@pytest.mark.parametrize(
    "text",
    [
        "would you mind bringing me scissors and packing tape?",  # a noun's describing word
        "I'm laminating my badge and getting my timesheet signed",  # no "mind" lead-in
        "would you mind? I'm busy and getting my form signed",  # another sentence
    ],
)
def test_gerunds_outside_a_mind_request_are_kept(text: str) -> None:
    assert joined_gerunds(text) == text


def test_the_joined_gerund_is_said_plain() -> None:
    said = joined_gerunds("would you mind laminating my badge, and getting my timesheet signed")
    assert said == "would you mind laminating my badge, and get my timesheet signed"
