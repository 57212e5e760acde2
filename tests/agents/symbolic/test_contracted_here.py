"""A where-question about a colleague with a sentence of context after it (fix135c, class 4):
"where is Zhang? the client's here" asked what to do, because "the client's here" was read as a
possessive of "here". "here" and "there" are never a noun a possessive owns, so "X's here" is
"X is here" (reading/screen/contracted_is.py, english.yaml contracted_whereabouts), a statement
of context, and the question about the colleague is answered in words."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("where is Zhang? the client's here", "Zhang Wei works at Desk 4"),
        ("where's Wang Fang? the client's here", "Wang Fang works at Desk 6"),
        ("where's Wang Fang? meeting starts in 5", "Wang Fang works at Desk 6"),
        ("where is Zhang? the courier's here to collect", "Zhang Wei works at Desk 4"),
    ],
)
def test_a_where_question_about_a_colleague_is_answered(text: str, where: str) -> None:
    frame = _default(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith(where), frame


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("where's Grace? the courier's here", "Grace Huang works at Desk 5"),
        ("where is Will? the client's there already", "Will Tanaka works at Desk 3"),
    ],
)
def test_the_same_in_another_office(text: str, where: str) -> None:
    frame = _harbour(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith(where), frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("the client's here", "the client is here"),
        ("the van's there already", "the van is there already"),
        ("Zhang's here stapler", "Zhang's here stapler"),  # a noun after it: left as said
    ],
)
def test_here_and_there_after_s_say_where(text: str, said: str) -> None:
    assert contracted_is(text)[0] == said


def test_a_where_question_about_a_thing_with_a_request_still_moves() -> None:
    frame = _default("where's Wang's stapler? can you bring it to me")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "lee")]
