"""Chat "r" for "are" ("mine r blunt", "they r in the drawer", "r u free") is read as "are"
where it stands between a subject and what is said of it, or opens a question before a
subject pronoun (``reading.chat_copula``), as "u" is read as "you"; elsewhere it is left."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic.reading.chat_copula import spelled_are


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("mine r blunt", "mine are blunt"),
        ("my pens r broken", "my pens are broken"),
        ("they r in the drawer", "they are in the drawer"),
        ("ours r not working", "ours are not working"),
        ("R u free?", "Are u free?"),
        # no subject and complement around it: as typed
        ("plan r", "plan r"),
        ("R&D report", "R&D report"),
        ("take Mr R Smith's pen", "take Mr R Smith's pen"),
        ("the letter r is missing", "the letter r is missing"),
        ("send the r file", "send the r file"),
    ],
)
def test_spelled_are(text: str, read: str) -> None:
    assert spelled_are(text) == read


@pytest.mark.parametrize(
    ("office", "who", "text", "task"),
    [
        (
            "default",
            "wang",
            "bring me Gao's scissors, mine r blunt",
            ("transfer", "scissors", "gao", "wang"),
        ),
        (
            "default",
            "wang",
            "bring me Gao's stapler, mine r broken",
            ("transfer", "stapler", "gao", "wang"),
        ),
        (
            "default",
            "wang",
            "r u able to bring me Gao's scissors",
            ("transfer", "scissors", "gao", "wang"),
        ),
        (
            "harbour",
            "may",
            "can u bring me Mark's ruler, mine r missing",
            ("transfer", "ruler", "mark", "may"),
        ),
    ],
)
def test_the_request_beside_it_is_done(
    office: str, who: str, text: str, task: tuple[str, str, str, str]
) -> None:
    assert tasks_of(office, text, who) == [task]
