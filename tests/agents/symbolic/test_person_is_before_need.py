"""A colleague's "'s" is "is" where a state, a doing or a preposition follows and the clause
goes on to "and needs" (fixer 84k, class 1: "Gao's busy with the review and needs a stapler,
take her mine" brought the speaker anyone's stapler besides taking Gao the speaker's: a wrong
hand-over). The colleague is the subject of "and needs", so the need is theirs and the request
beside it meets it: one task (``reading/screen/person_is.py``). A possessive that names a thing
and a clause with no need joined read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "may")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # the class's analogue, and the full form that was right
        (
            "Gao's busy with the review and needs a stapler, take her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
        (
            "Gao is busy with the review and needs a stapler, take her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
        # variants: a doing, a past participle, a preposition, an adverb before the need
        (
            "Gao's doing the slides and needs a stapler, take her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
        (
            "Gao's doing slides and needs a stapler, take her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
        (
            "Gao's swamped and really needs scissors, bring her mine",
            ("transfer", "scissors", "mao", "gao"),
        ),
        (
            "Hu's preparing the budget and needs a pen, take him mine",
            ("transfer", "pen", "mao", "hu"),
        ),
        (
            "Gao's in a meeting and needs a stapler, take her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
    ],
)
def test_the_need_is_the_colleagues_on_the_default_office(
    text: str, task: tuple[str, str, str, str]
) -> None:
    assert _tasks(_default(text)) == [task]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Mark's busy with the audit and needs tape, take him mine",
            ("transfer", "tape", "may", "mark"),
        ),
        (
            "Mark's working on the mailout and needs tape, take him mine",
            ("transfer", "tape", "may", "mark"),
        ),
        (
            "Mark's sorting invoices and needs a ruler, take him Grace's",
            ("transfer", "ruler", "grace", "mark"),
        ),
        (
            "Rose's with a client and wants a calculator, bring her Mark's",
            ("transfer", "calculator", "mark", "rose"),
        ),
    ],
)
def test_the_need_is_the_colleagues_on_harbour(text: str, task: tuple[str, str, str, str]) -> None:
    assert _tasks(_harbour(text)) == [task]


def test_a_possessive_before_the_speakers_own_need_is_still_one() -> None:
    # must not change: "Gao's stapler" is hers; nothing is taken to Gao
    frame = _default("Gao's stapler is broken and I need one")
    assert all(t.recipient != "gao" for t in frame.tasks)
    assert frame.hints and frame.hints[0].person == "gao"


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        # must not change: where she is, no need joined
        (_default, "Gao's at her desk, take her my stapler", ("transfer", "stapler", "mao", "gao")),
        # must not change: an adjective before her thing is a possessive's
        (
            _default,
            "Gao's old stapler is broken and needs fixing, bring her mine",
            ("transfer", "stapler", "mao", "gao"),
        ),
        (_harbour, "Mark's at his desk, take him my tape", ("transfer", "tape", "may", "mark")),
    ],
)
def test_neighbours_read_as_before(
    read: ReadFrame, text: str, task: tuple[str, str, str, str]
) -> None:
    assert _tasks(read(text)) == [task]
