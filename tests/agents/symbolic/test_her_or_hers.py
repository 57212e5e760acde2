""" "bring her lunch": "her" after a giving verb is whom the thing goes to or whose it is.
When the sentences before are about her ("Zhang can't get away", "Chen's busy"), the thing
goes to her; when nothing decides, the reader asks "..., or to you?" and the answer settles
it; a colleague's own thing is never handed to the speaker on a guess (fix154a class 3:
"Ngozi's stuck with a client, could you bring her lunch up from the fridge?" handed Ngozi's
lunch to the speaker). "bring me her lunch" and "bring her lunch to me" stay the speaker's."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")
_answered = answered_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "whose"),
    [
        ("Zhang can't get away, can you bring her lunch from the fridge", "zhang"),
        ("Zhang's in a meeting, could you bring her lunch", "zhang"),
        ("Zhang is stuck with a client, could you bring her lunch up from the fridge?", "zhang"),
        ("Chen's busy, grab her lunch from the fridge pls", "chen"),
    ],
)
def test_her_thing_goes_to_her_when_the_sentence_before_is_about_her(text: str, whose: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", whose, whose)
    ]


def test_her_lunch_goes_to_her_in_harbour() -> None:
    frame = _harbour("Grace is stuck in a meeting, can you bring her lunch from the fridge")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "grace", "grace")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Is Zhang in? bring her lunch",
        "print my file for Zhang and bring her lunch",
        "Zhang's lunch is in the fridge, bring her lunch",  # told of her lunch, not of her
    ],
)
def test_nothing_deciding_asks_to_her_or_to_you(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame
    assert frame.question == "Should Zhang Wei's lunch go to Zhang Wei, or to you?"


@pytest.mark.parametrize(
    ("answer", "recipient"),
    [("to her", "zhang"), ("Zhang", "zhang"), ("to me", "lee"), ("me please", "lee")],
)
def test_the_answer_settles_whom(answer: str, recipient: str) -> None:
    frame = _answered("Is Zhang in? bring her lunch", [answer])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "zhang", recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Zhang can't get away, can you bring me her lunch from the fridge",
        "Zhang can't get away, can you bring her lunch to me",
    ],
)
def test_a_recipient_said_keeps_her_as_the_owner(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "zhang", "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Zhang is off sick, grab her stapler",  # at her desk: hers, lent to me
        "Zhang's on holiday, can you get her stapler",
        "Is Zhang in? grab her stapler",
    ],
)
def test_a_thing_at_her_own_desk_is_hers_handed_to_me(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "lee")
    ], frame


def test_her_coffee_is_made_for_her_when_the_sentence_before_is_about_her() -> None:
    frame = _default("Wang's in a meeting, can you bring her coffee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "coffee", "wang")
    ], frame


def test_him_and_his_said_apart_are_unchanged() -> None:
    frame = _default("Wang's in a meeting, could you bring him his coffee")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("produce", "wang")], frame
