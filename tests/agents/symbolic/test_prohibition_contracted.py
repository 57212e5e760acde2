"""A prohibition with its "is" contracted is the same wish as the full form (fixer 84k, class
4: "nobody's to use the microwave till I've cleaned it" asked "Which item do you mean for me
to heat?", while "no one is to touch the printer until it's fixed" was answered in words).
"nobody's"/"no one's" before "to" or a past participle is "nobody is"
(``reading/prohibition_contracted.py``); before a noun it is a possessive, before a present
participle a fact: both read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _answered_in_words(frame: TaskFrame) -> bool:
    return (
        frame.tasks == []
        and frame.question is None
        and frame.decline is not None
        and "I can't keep people away from things" in frame.decline
    )


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue, and the full form it means
        "nobody's to use the microwave till I've cleaned it",
        "nobody is to use the microwave till I've cleaned it",
        # variants: other subjects, other verbs, other things
        "no one's to borrow my stapler until Friday",
        "noone's allowed to touch the printer today",
        "nobody's meant to open the fridge before lunch",
    ],
)
def test_a_contracted_prohibition_is_a_wish_on_the_default_office(text: str) -> None:
    assert _answered_in_words(_default(text))


@pytest.mark.parametrize(
    "text",
    [
        "nobody's to use the laminator till it's been serviced",
        "no one's allowed to borrow my tape this week",
        "nobody's to touch the kettle, it's broken",
    ],
)
def test_a_contracted_prohibition_is_a_wish_on_harbour(text: str) -> None:
    assert _answered_in_words(_harbour(text))


def test_a_possessive_nobody_is_no_wish() -> None:
    # must not change: "nobody's fault" is a possessive; the request beside it is done
    frame = _default("it's nobody's fault, bring me a stapler")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "mao")]


def test_what_is_going_on_is_no_wish() -> None:
    # must not change: "nobody's using the kettle" tells a fact; the request beside it is done
    frame = _harbour("nobody's using the kettle, boil me some water")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("produce", "may")]
