"""Fixer fix180c class 3: "Can someone lend me a stopwatch for the audit?" asked "Whose
stopwatch do you mean?" and could not read the answer "Anyone's, any will do."

(a) "for the audit", "for the 3pm review": an operation's noun ending a phrase opened by "the"
after "for", right after a thing asked for that is not the speaker's own, names an occasion
(why), as "for the contract signing" does (``_objects._occasion_noun``): no work on the thing,
so its owner does not matter. (b) "Anyone's", "doesn't matter", "whoever's" to "Whose X do
you mean?" means any owner's (``several_owners.any_owner_meant``)."""

from __future__ import annotations

import pytest

from helpers.reading import answered_reader, frame_reader
from helpers.swab_clinic import swab_clinic

_read = frame_reader(swab_clinic, "ines")
_answered = answered_reader(swab_clinic, "ines")


def _tasks(text: str, answers: tuple[str, ...] = ()) -> list[tuple[str, str | None, str | None]]:
    frame = _answered(text, list(answers)) if answers else _read(text)
    assert frame.question is None, frame
    return [(t.kind, t.item, t.owner) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Can someone lend me a stopwatch for the 3pm audit?",
        "Can someone lend me a stopwatch for the fitness audit?",
        "can someone lend me a stopwatch for the 3pm review",
        # must not change: read so before
        "can someone lend me a stopwatch for the review",
        "could I borrow a stopwatch for the annual audit tomorrow",
    ],
)
def test_an_operation_noun_of_an_occasion_is_why(text: str) -> None:
    assert _tasks(text) == [("transfer", "stopwatch", None)]


def test_a_colleagues_thing_for_an_occasion_is_theirs_lent() -> None:
    assert _tasks("can I borrow Tariq's stopwatch for the quarterly audit") == [
        ("transfer", "stopwatch", "tariq")
    ]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # must not change: the work asked on the thing, no thing before the occasion
        ("audit Tariq's stopwatch for me", ("heat", "stopwatch", "tariq")),
        ("calibrate Tariq's stopwatch before the audit", ("heat", "stopwatch", "tariq")),
    ],
)
def test_the_work_asked_is_still_work(text: str, task: tuple[str, str, str]) -> None:
    assert _tasks(text) == [task]


@pytest.mark.parametrize(
    "answer", ["Anyone's, any will do.", "doesn't matter", "whoever's", "any", "don't mind"]
)
def test_any_owner_answers_whose(answer: str) -> None:
    text = "could you calibrate the stopwatch?"
    assert _read(text).question == "Whose stopwatch do you mean?"
    assert _tasks(text, (answer,)) == [("heat", "stopwatch", None)]


@pytest.mark.parametrize(("answer", "owner"), [("Tariq's", "tariq"), ("Tariq's will do", "tariq")])
def test_a_named_owner_answers_whose(answer: str, owner: str) -> None:
    assert _tasks("could you calibrate the stopwatch?", (answer,)) == [("heat", "stopwatch", owner)]


@pytest.mark.parametrize("answer", ["not anyone's", "mine"])
def test_no_owner_said_is_asked_again(answer: str) -> None:
    frame = _answered("could you calibrate the stopwatch?", [answer])
    assert frame.tasks == [] and "Whose stopwatch" in (frame.question or ""), frame
