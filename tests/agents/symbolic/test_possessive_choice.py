"""A bare possessive offered as the choice (class 79a-2): "stapler pls, Wang's if he's not
using it" borrowed anyone's stapler (the possessive and its condition were a statement).
A colleague's possessive with the thing left out, set off after the request and followed by
nothing or by a condition, names whose one is asked for: the owner is asked (which covers
the condition). "Wang's is broken" and "not Wang's" say the opposite and stay as they were."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.accepted_owner import accepted_owners
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_READERS = {
    default_office: frame_reader(default_office, "mao"),
    harbour_office: frame_reader(harbour_office, "will"),
}


def _tasks(office: OfficeOf, text: str) -> list[tuple[str, str, str | None, str]]:
    frame = _READERS[office](text)
    assert frame.question is None, frame.question
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        (
            default_office,
            "stapler pls, Wang's if he's not using it",
            ("transfer", "stapler", "wang", "mao"),
        ),
        (
            default_office,
            "can I have a stapler, Wang's if he isn't using it",
            ("transfer", "stapler", "wang", "mao"),
        ),
        # variants: other words, other conditions, nothing after the possessive
        (default_office, "stapler pls, Wang's", ("transfer", "stapler", "wang", "mao")),
        (
            default_office,
            "could you grab me a pen, Chen's as long as she doesn't mind",
            ("transfer", "pen", "chen", "mao"),
        ),
        (
            default_office,
            "some scissors please - Zhou's would be fine",
            ("transfer", "scissors", "zhou", "mao"),
        ),
        (
            harbour_office,
            "an umbrella please, Rose's if she doesn't need it",
            ("transfer", "umbrella", "rose", "will"),
        ),
        (
            harbour_office,
            "calculator pls, Grace's unless she's using it",
            ("transfer", "calculator", "grace", "will"),
        ),
        (harbour_office, "tape please, Mark's", ("transfer", "tape", "mark", "will")),
    ],
)
def test_the_possessive_offered_names_whose_one(
    office: OfficeOf, text: str, task: tuple[str, str, str, str]
) -> None:
    assert _tasks(office, text) == [task]


@pytest.mark.parametrize(
    "text",
    [
        "can I have a stapler? Wang's is broken",
        "can I have a stapler, not Wang's",
    ],
)
def test_a_possessive_said_against_is_not_the_choice(text: str) -> None:
    assert _tasks(default_office, text) == [("transfer", "stapler", None, "mao")]


@pytest.mark.parametrize(
    "text",
    [
        "could you take this book to Wang's if he's in",  # a place, no pause before it
        "can I have a stapler? Wang's is broken",
        "a stapler, Wangs if he's not using it",  # no possessive
        "a stapler, Wang's one if he's free",  # the thing is said: the frames read it
        "Bring me Lee's stapler. Not Wang's, Wang's.",  # a correction: the corrections'
        "bring me Zhang's stapler, Wang's",  # an owner said already: not offered as a choice
    ],
)
def test_what_is_no_offered_possessive_is_left_as_written(text: str) -> None:
    assert accepted_owners(text, lambda w: w.lower().startswith(("wang", "zhang", "lee"))) == text


def test_the_rewrite_reads_the_condition_away() -> None:
    said = accepted_owners("stapler pls, Wang's if he's not using it", lambda w: True)
    assert said == "stapler pls. Wang's please"
