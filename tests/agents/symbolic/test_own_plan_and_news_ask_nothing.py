"""Fixer fix59c class 1: the speaker's own plan ("might heat my soup a bit later", "probably
gonna grab a coffee after the call", "think I'll print my slides tomorrow") and news closed
by a tag ("the late shows in the courtyard start at 10 this summer btw") ask nothing: noted,
nothing done, nothing asked (``screen.own_intention``, ``screen.fyi``). A plan asked of the
robot ("might you ...", "could you ..."), a need put off beside a request, or a request after
a tag are read as before."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "might heat my soup a bit later",
        "probably gonna grab a coffee after the call",
        "think I'll print my slides tomorrow",
        "I think I'll print my document later",
        "the sun's finally out, might eat lunch outside",
        "im probably gonna copy my document after lunch",
        "summer screenings on the roof start at 9 this year btw",
        "evening classes in the annex start at 6 from next week btw",
        "fyi the loading bay closes at 4 on fridays",
        "the late shows in the courtyard start at 10 this summer btw",
    ],
)
def test_a_plan_or_news_is_noted(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted"), frame


@pytest.mark.parametrize(
    "text", ["might you heat my soup", "could you heat my soup", "maybe heat my soup"]
)
def test_a_plan_asked_of_me_is_still_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is not None and frame.question.startswith("Shall I heat"), frame


def test_a_need_put_off_with_a_request_after_it_asks() -> None:
    frame = parser("default").parse("I might need my soup heated, could you", "lee")
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("btw can you print my slides", [("print", "file", "lee", "lee")]),
        ("gonna need a coffee, can you get me one", [("produce", "coffee", None, "lee")]),
        (
            "I'm probably gonna print my slides later, can you get me a stapler",
            [("transfer", "stapler", None, "lee")],
        ),
    ],
)
def test_a_request_beside_them_is_done(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    assert tasks_of("default", text, "lee") == tasks
