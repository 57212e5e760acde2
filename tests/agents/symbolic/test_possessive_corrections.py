"""A colleague's bare possessive set off after the thing asked for corrects or picks its owner
(fixer 82f, class 2): "can I have a stapler, not Wang's, Zhang's" fetched anyone's stapler AND
Zhang's, "bring me Hu's stapler, Gao's" fetched both. "not X's, Y's" is one thing, Y's; "X's
stapler, Y's" is a correction to Y's (``reading/possessive_corrections.py``). Two things
named ("Wang's stapler and Zhang's scissors", "Wang's stapler, Zhang's too"), a refusal alone
("not Zhang's") and a possessive that says something else ("Zhang's is broken") read as
before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _got(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        # the class's analogues (Hu and Gao keep staplers; Lee and Lin keep none)
        ("can I have a stapler, not Wang's, Zhang's", "stapler", "zhang"),
        ("bring me Hu's stapler, Gao's", "stapler", "gao"),
        # variants: the refusal after the choice, "but", "please", correction words
        ("can I have a stapler, Zhang's, not Wang's", "stapler", "zhang"),
        ("bring me a stapler, not Wang's but Gao's", "stapler", "gao"),
        ("can I have some scissors, not Sun's, Lin's please", "scissors", "lin"),
        ("bring me Hu's stapler, sorry I mean Gao's", "stapler", "gao"),
        ("can I have a stapler, no, Zhang's", "stapler", "zhang"),
        ("can I have a stapler, Zhang's please", "stapler", "zhang"),
        ("bring me Hu's stapler, Gao's. thanks", "stapler", "gao"),
        ("bring me Hu's stapler, no wait, Gao's", "stapler", "gao"),
    ],
)
def test_a_bare_possessive_after_the_thing_is_its_one_owner(
    text: str, item: str, owner: str
) -> None:
    assert _got(_default(text)) == [(item, owner, "mao")]


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me Mark's ruler, Grace's", "ruler", "grace"),
        ("can I have a calculator, not Will's, Dawn's please", "calculator", "dawn"),
        ("could you get me a charger - not Bill's, Jack's", "charger", "jack"),
    ],
)
def test_a_bare_possessive_after_the_thing_is_its_one_owner_harbour(
    text: str, item: str, owner: str
) -> None:
    assert _got(_harbour(text)) == [(item, owner, "may")]


@pytest.mark.parametrize(
    ("text", "got"),
    [
        # neighbours: two things named, a refusal alone, a possessive that says more
        (
            "bring me Wang's stapler and Zhang's scissors",
            [("stapler", "wang", "mao"), ("scissors", "zhang", "mao")],
        ),
        (
            "bring me Wang's stapler, Zhang's too",
            [("stapler", "wang", "mao"), ("stapler", "zhang", "mao")],
        ),
        ("bring me Wang's stapler, not Zhang's", [("stapler", "wang", "mao")]),
        ("can I have a stapler, not Wang's", [("stapler", None, "mao")]),
        ("I need Wang's stapler, Zhang's is broken", [("stapler", "wang", "mao")]),
        ("can I have a stapler, Wang's if he's not using it", [("stapler", "wang", "mao")]),
        # the thing asked for in the sentence before: the corrections across sentences read it
        ("Bring me Hu's stapler. Not Hu's, Gao's.", [("stapler", "gao", "mao")]),
    ],
)
def test_other_possessives_read_as_before(
    text: str, got: list[tuple[str | None, str | None, str | None]]
) -> None:
    assert _got(_default(text)) == got


def test_two_owners_in_one_phrase_still_asked() -> None:
    frame = _default("Wang's and Zhang's staplers")
    assert frame.tasks == [] and frame.question is not None
    assert "Wang Fang's stapler" in frame.question and "Zhang Wei's stapler" in frame.question


def test_two_things_named_on_harbour_stay_two() -> None:
    assert _got(_harbour("bring me Mark's ruler, Grace's too")) == [
        ("ruler", "mark", "may"),
        ("ruler", "grace", "may"),
    ]
