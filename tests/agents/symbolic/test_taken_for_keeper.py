"""A service on one's own thing, the thing taken "for" the colleague who keeps that service:
"my bow needs rehairing, can you take it down to the store for Frank?". The keeper does the
work and the thing comes back to its owner; it is not handed to the keeper and left there
(``reading.taken_for_keeper``). With no service the named colleague runs, "take it to X" /
"take it over for X" is a delivery, as before."""

from __future__ import annotations

import functools

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import Task
from helpers import office_builder as ob
from helpers.music_school import music_school, raw_music_school


@functools.cache
def _music() -> InstructionParser:
    return InstructionParser(music_school())


def _done(task: Task) -> tuple[str | None, str | None, str | None, str]:
    return (task.item, task.owner, task.actor, task.recipient)


@pytest.mark.parametrize(
    ("text", "item", "keeper"),
    [
        ("My bow needs rehairing, can you take it down to the store for Frank?", "bow", "frank"),
        (
            "my guitar needs restringing, could you drop it at the workshop for Nell?",
            "guitar",
            "nell",
        ),
        (
            "my trumpet could do with a polish, can you take it over for Nell please",
            "trumpet",
            "nell",
        ),
    ],
)
def test_the_keeper_does_the_work_and_it_comes_back_music_school(
    text: str, item: str, keeper: str
) -> None:
    frame = _music().parse(text, "tom")
    assert [_done(t) for t in frame.tasks] == [(item, "tom", keeper, "tom")], frame


@pytest.mark.parametrize(
    "text",
    [
        "my badge needs laminating, can you take it down for Sue?",
        "my badge needs laminating, can you take it to the laminator for Sue?",
    ],
)
def test_the_keeper_does_the_work_and_it_comes_back_harbour(text: str) -> None:
    frame = parser("harbour").parse(text, "bill")
    assert [_done(t) for t in frame.tasks] == [("badge", "bill", "sue", "bill")], frame


def test_a_carrying_with_no_service_is_a_delivery() -> None:
    # must not change: nothing to be done to it, so the colleague named gets it
    assert tasks_of("default", "can you take my stapler to Wang", "zhang") == [
        ("transfer", "stapler", "zhang", "wang")
    ]
    frame = _music().parse("can you take my bow over for Frank", "tom")
    assert [_done(t) for t in frame.tasks] == [("bow", "tom", None, "frank")]


def test_a_service_the_named_colleague_does_not_run_is_not_theirs_to_do() -> None:
    # must not change: Xu keeps the printer, which fixes nothing, so "for Xu" is no doer
    frame = parser("default").parse(
        "my stapler needs fixing, can you take it to the print room for Xu?", "zhang"
    )
    assert all(t.actor is None for t in frame.tasks), frame


@pytest.mark.parametrize(
    "text",
    [
        "My bow needs rehairing, can you take it to Frank to rehair?",
        "can you take my bow to Frank to rehair",
        "can you take my bow to Frank for rehairing",
    ],
)
def test_sent_to_the_keeper_for_work_no_dictionary_knows(text: str) -> None:
    # "rehair" is the office's own verb, unknown to the dictionary: its forms are still read
    # as the work (``sent_for_service``), so Frank rehairs it and it comes back, once
    frame = _music().parse(text, "tom")
    assert [_done(t) for t in frame.tasks] == [("bow", "tom", "frank", "tom")], frame


def _with_a_surname_frank() -> InstructionParser:
    """The music school where Ada's surname is Frank: "Frank" names Frank Osei by his given
    name and Ada Frank by her surname."""
    raw = raw_music_school()
    for person in raw["people"]:
        if person["id"] == "ada":
            person["name"] = "Ada Frank"
    return InstructionParser(ob.parsed(lambda: raw)())


def test_of_two_people_a_name_says_the_one_who_keeps_the_service_is_meant() -> None:
    frame = _with_a_surname_frank().parse(
        "My bow needs rehairing, can you take it down to the store for Frank?", "ines"
    )
    assert frame.question is None, frame
    assert [_done(t) for t in frame.tasks] == [("bow", "ines", "frank", "ines")], frame
