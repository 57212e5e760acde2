"""A remedy asked as a question is offered, not fetched: "got anything for my knees? they're
scraped" (fixer fix189c; the round's own offices and sentences were never read).

Only a request moves the robot. "got anything for ...?", "anything for a headache?" and "...,
anything to sort it out?" are questions: where one thing of the office fits, the answer says
so and asks "Shall I bring you one?", and the yes brings it; where several fit, which is asked,
as before; "..., please" and "bring me something to sort it out" ask for it and bring it."""

from __future__ import annotations

import pytest

from helpers.costume_shop import costume_shop
from helpers.reading import answered_reader, frame_reader
from helpers.safety_bench import safety_bench

_bench = frame_reader(safety_bench, "lee")
_bench_answered = answered_reader(safety_bench, "lee")
_shop = frame_reader(costume_shop, "wang")
_shop_answered = answered_reader(costume_shop, "wang")


@pytest.mark.parametrize(
    "text",
    [
        "got anything for my hands? they're sore",
        "anything for my sore hands?",
        "do you have anything for my sore hands?",
        "have you got anything for my hands? they're raw",
    ],
)
def test_a_complaint_asked_offers_the_one_thing(text: str) -> None:
    frame = _bench(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "hand cream" in frame.question and "Shall I bring you" in frame.question, frame


def test_the_yes_brings_it() -> None:
    frame = _bench_answered("anything for my sore hands?", ["yes please"])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "hand_cream", "lee")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "my coat is covered in dog hair, anything to sort it out?",
        "my coat is covered in dog hair, something to sort it out?",
        "my coat is covered in dog hair, got anything to sort it out?",
    ],
)
def test_a_remedy_asked_after_a_problem_offers_the_one_thing(text: str) -> None:
    frame = _shop(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "lint roller" in frame.question and "Shall I bring you" in frame.question, frame


def test_the_yes_to_a_remedy_after_a_problem_brings_it_and_a_no_does_nothing() -> None:
    text = "my coat is covered in dog hair, anything to sort it out?"
    yes = _shop_answered(text, ["yes"])
    assert [(t.kind, t.item) for t in yes.tasks] == [("transfer", "lint_roller")], yes
    no = _shop_answered(text, ["no"])
    assert no.tasks == [] and no.decline is not None, no


# -- must not change --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "my coat is covered in dog hair, bring me something to sort it out",
        "my coat is covered in dog hair, something to sort it out please",
    ],
)
def test_a_remedy_asked_for_is_brought(text: str) -> None:
    frame = _shop(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "lint_roller")], frame


def test_a_complaint_asked_with_please_is_brought() -> None:
    frame = _bench("anything for my sore hands, please")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "hand_cream")], frame


def test_several_that_fit_are_still_asked_which() -> None:
    frame = _bench("got anything for my cut finger?")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Which would you like"), frame
