"""Blind rounds 43-48, class J4: a colleague's title that holds a possessive ("the Judge's
Clerk", "the Director's PA") is one name of the office, whole, also with a possessive of its
own ("the Judge's Clerk's keys"): the lexicon reads the office's aliases with an inner
possessive as it reads its things' names ("a reporter's notebook"). A signature said as put
on a paper ("could the practice manager put her signature on my timesheet?") is that
person signing it (``idioms.signature_put``). On ``helpers.county_court``; the rounds' own
offices and sentences were never read."""

from __future__ import annotations

import pytest

from helpers.county_court import county_court
from helpers.reading import frame_reader

_frame = frame_reader(county_court, "tess")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _frame(text)
    assert frame.question is None, frame.question
    return [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("May I borrow the Judge's Clerk's keys for the records basement?", "vera"),
        ("could you bring me the judge's clerk's courtroom keys", "vera"),
        ("can I borrow the Head of Department's stapler", "wyn"),
        ("grab me the Director's PA's timesheet please", "yara"),
    ],
)
def test_a_possessive_title_owns(text: str, owner: str) -> None:
    assert [o for _, _, o, _ in _tasks(text)] == [owner]


@pytest.mark.parametrize(
    ("text", "actor"),
    [
        ("can the judge's clerk sign my form", "vera"),
        ("ask the Director's PA to sign my timesheet", "yara"),
        ("could the practice manager put her signature on my timesheet?", "yara"),
        ("could Yara put her signature on my timesheet?", "yara"),
        ("can you get Wyn to put his signature on my form", "wyn"),
        ("could the Judge's Clerk add her signature to my timesheet please", "vera"),
        ("I need the Director's PA's signature on my timesheet", "yara"),
    ],
)
def test_a_possessive_title_signs(text: str, actor: str) -> None:
    assert _tasks(text) == [("sign", "timesheet", "tess", actor)]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Vera's stapler", "vera"),
        ("can I borrow Omar's courtroom keys", "omar"),
    ],
)
def test_a_name_is_still_a_name(text: str, owner: str) -> None:
    assert [o for _, _, o, _ in _tasks(text)] == [owner]


def test_a_title_nobody_holds_is_asked() -> None:
    assert _frame("bring me the judge's keys").question is not None
