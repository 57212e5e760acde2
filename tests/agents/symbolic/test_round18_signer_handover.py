"""Blind round 18, class 1: "P needs to sign my X. Take it over to her (and bring it back)": the
clause that takes the paper to the signer already named is the way to the signer, not whom the
signed paper goes to; it comes back to the requester unless someone else is named (on
``helpers.histology_lab``; the round's own office and sentences were never read)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.histology_lab import histology_lab
from helpers.reading import frame_reader

_frame = frame_reader(histology_lab, "bea")


def _signs(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Wren needs to sign my timesheet. Could you take it over to her and bring it back?",
        "Wren needs to sign off my coshh form before I can use the phenol, can you take it to her?",
        "Wren needs to sign my holiday form, could you run it over to her?",
        "Wren needs to sign my timesheet, take it to her please",
        "can you take my timesheet to Wren to sign and bring it back",
    ],
)
def test_the_signed_paper_comes_back_to_the_requester(text: str) -> None:
    assert _signs(_frame(text)) == [("sign", "timesheet", "bea", "bea", "wren")]


def test_a_recipient_named_after_the_signer_still_gets_the_paper() -> None:
    frame = _frame("Wren needs to sign my timesheet, can you take it to her and then on to Ivy")
    assert _signs(frame) == [("sign", "timesheet", "bea", "ivy", "wren")]


def test_a_plain_hand_over_to_a_person_is_unchanged() -> None:
    frame = _frame("could you take my timesheet to Ivy")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "timesheet", "ivy")
    ]


def test_a_question_about_signing_moves_nothing() -> None:
    assert _frame("does Wren need to sign my timesheet?").tasks == []
