"""A group said as "them" with no colleague named before it, the speaker said later as the one
who receives ("can we get them some water? bring it to me at reception"): the thing goes to
the speaker, nothing asked (``reading.group_recipient``); before, "Who do you mean by
'them'?" was asked, which the speaker cannot answer with a colleague's name (fix213a class
3). With no later recipient "them" is still asked about, and so is "him"."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

_WATER = ("produce", "water", None, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "the visitors loved the tour!! can we get them some water? bring it to me at reception",
        "can you get them some water and bring it to me",
        "the auditors are here, could you fetch them some water? bring it to me please",
    ],
)
def test_a_group_whose_thing_comes_to_the_speaker(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is None, frame
    assert tasks_of("default", text, "lee") == [_WATER]


@pytest.mark.parametrize(
    "text",
    [
        "the visitors are thirsty, can you get them some water",
        "can you get him some water? bring it to me",
    ],
)
def test_them_with_no_recipient_later_is_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Who do you mean by"), frame


def test_them_after_a_colleague_is_that_colleague() -> None:
    assert tasks_of("default", "Wang is thirsty, can you get them some water", "lee") == [
        ("produce", "water", None, "wang")
    ]
