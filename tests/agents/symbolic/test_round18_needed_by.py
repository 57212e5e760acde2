"""Blind round 18, class 2: whom a request is for, said after it ("can you print my file? it's
Ivy who needs the hard copy not me", "Ivy needs it, not me", "it's for Ivy"): the named person
gets what the request makes, not the requester (``reading.needed_by``, on
``helpers.histology_lab``; the round's own office and sentences were never read)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.histology_lab import histology_lab
from helpers.reading import frame_reader

_frame = frame_reader(histology_lab, "bea")


def _moves(frame: TaskFrame) -> list[tuple[str, str | None, str]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can you print my file? it's ivy who needs the hard copy not me",
        "can you print my protocol? Ivy needs it, not me",
        "print my file please, it's for Ivy",
        "print my file, Ivy's the one who needs it",
        "can you print my file? it is Ivy who needs it, not me",
    ],
)
def test_the_person_said_to_need_it_gets_the_printout(text: str) -> None:
    assert _moves(_frame(text)) == [("print", "file", "ivy")]


def test_a_hand_over_goes_to_the_person_said_to_need_it() -> None:
    frame = _frame("can you bring me Jude C's forceps? it's Wren who needs them, not me")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("forceps", "jude_c", "wren")]


@pytest.mark.parametrize(
    "text",
    [
        "can you print my file? it's for me, not Ivy",
        "print my file please. is it for Ivy?",
        "can you print my file please",
    ],
)
def test_near_misses_still_come_to_the_requester(text: str) -> None:
    assert _moves(_frame(text)) == [("print", "file", "bea")]


def test_a_question_about_who_needs_it_moves_nothing() -> None:
    assert _frame("does Ivy need my file printed?").tasks == []
