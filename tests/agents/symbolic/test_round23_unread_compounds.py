"""Blind rounds 23-24, class 1: a part of a two-part request that names the office's file by
a compound the office does not list ("Maren's vet notes" where the file is the "session
notes", "my ride briefing" where it is the "briefing pack") is asked about, never dropped
while the other part is done and "Done" reported. On sentences of our own against a riding
stables (the rounds' office and sentences were never read)."""

from __future__ import annotations

import pytest

from helpers.reading import answered_reader, frame_reader
from helpers.riding_stables import stables

_frame = frame_reader(stables, "ines")
_answered = answered_reader(stables, "ines")


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        (
            "Could I borrow somebody's stopwatch and get Maren's vet notes forwarded to me?",
            "Maren's vet notes",
        ),
        ("fwd my ride briefing to Ulla and get her to sign my form too pls", "my ride briefing"),
        ("lend me a stopwatch and send Ulla my briefing", "my briefing"),
        ("get Ulla to sign my form and forward the vet notes to Tobiah", "the vet notes"),
    ],
)
def test_an_unread_compound_is_asked_about_and_nothing_moves(text: str, phrase: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None
    assert f"“{phrase}”" in frame.question


def test_the_answer_takes_the_parts_place() -> None:
    frame = _answered(
        "fwd my ride briefing to Ulla and get her to sign my form too pls",
        ["my briefing pack"],
    )
    rows = [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]
    assert rows == [
        ("send_file", "session_file", "ines", "ulla", None),
        ("sign", "form", "ines", "ines", "ulla"),
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "fwd my session notes to Ulla and get her to sign my form too pls",
            [("send_file", "session_file"), ("sign", "form")],
        ),
        (
            "send my briefing pack to Ulla and lend me a stopwatch",
            [("send_file", "session_file"), ("transfer", "stopwatch")],
        ),
        ("lend me a stopwatch, I'm late for the vet", [("transfer", "stopwatch")]),
        ("get Ulla to sign my form, it's for the ride", [("sign", "form")]),
    ],
)
def test_names_the_office_lists_and_plain_talk_are_read_as_before(
    text: str, expected: list[tuple[str, str]]
) -> None:
    assert [(t.kind, t.item) for t in _frame(text).tasks] == expected


@pytest.mark.parametrize(
    "text",
    ["thanks for the vet notes", "did you send my ride briefing?", "don't fwd my ride briefing"],
)
def test_thanks_a_question_or_a_negation_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []
