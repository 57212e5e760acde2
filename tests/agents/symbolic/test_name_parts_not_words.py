"""No ordinary English word names a colleague, by itself or with an added "s", and no middle
part of a full name ("Thị" of "Nguyễn Thị Mai", the particles "van", "de la", "ap", "bin")
names one alone (``core.name_parts``, ``reading.bare_possessives``): "photocopy *this*
document for Wang" is the requester's document, never Thị's. The first and last words of a
name, its aliases and the surname with its particles ("van Dijk", "de la Cruz") still name
their bearer, and a name that is also a word keeps its reading by syntax ("to Said")."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from helpers.many_part_names import (
    ADDED,
    default_with_many_part_names,
    harbour_with_many_part_names,
)
from helpers.reading import frame_reader

_default = frame_reader(default_with_many_part_names, "zhang")
_harbour = frame_reader(harbour_with_many_part_names, "may")

Row = tuple[str, str | None, str | None, str]


def _tasks_default(text: str) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _default(text).tasks]


def _tasks_harbour(text: str) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _harbour(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Could you photocopy this document for Wang?",  # the class's own shape
        "could you copy this contract for Wang please",
        "pls photocopy this invoice for wang",
        "Can you copy this form and give it to Wang?",
    ],
)
def test_this_before_a_paper_is_the_requesters_not_thi(text: str) -> None:
    tasks = _tasks_default(text)
    assert tasks, text
    assert all(owner == "zhang" for _, _, owner, _ in tasks), tasks
    assert {r for *_, r in tasks} == {"wang"}


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Could you scan this document for Rose?", "rose"),
        ("can you scan this letter for Mark", "mark"),
    ],
)
def test_this_before_a_paper_on_harbour(text: str, recipient: str) -> None:
    tasks = _tasks_harbour(text)
    assert tasks, text
    assert all(owner == "may" for _, _, owner, _ in tasks), tasks
    assert {r for *_, r in tasks} == {recipient}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # must not change: the person's own names, aliases and surname with its particles
        ("bring me Mai's stapler", [("transfer", "stapler", "mai", "zhang")]),
        ("take my stapler to van Dijk", [("transfer", "stapler", "zhang", "jan")]),
        ("give my report to de la Cruz", [("transfer", "document", "zhang", "maria")]),
        ("bring me Rhys's stapler", [("transfer", "stapler", "rhys", "zhang")]),
        ("bring me Thi's stapler", [("transfer", "stapler", "thi", "zhang")]),
        ("give my report to Omar bin Said", [("transfer", "document", "zhang", "omar")]),
    ],
)
def test_names_and_surnames_still_name_their_bearer(text: str, expected: list[Row]) -> None:
    assert _tasks_default(text) == expected


def test_a_name_that_is_a_word_in_a_name_slot_keeps_its_reading() -> None:
    assert _tasks_default("take my stapler to Said") == [("transfer", "stapler", "zhang", "omar")]


def test_a_middle_word_is_no_name_by_itself() -> None:
    frame = _default("bring me Văn's stapler")
    assert not any(t.owner in ADDED for t in frame.tasks)


_WORDS = ("this", "than", "van", "de", "an", "bin", "ap", "la", "said", "his", "thus", "these")
_DEFAULT_FORMS = (
    "could you photocopy {w} document for Wang",
    "please copy {w} report for Chen",
    "take {w} stapler to Wang",
    "can you bring me {w} stapler",
    "print {w} file for Chen please",
)
_HARBOUR_FORMS = (
    "could you scan {w} document for Rose",
    "take {w} ruler to Mark",
    "can you bring me {w} ruler",
)


def _nobody_added(frame_text: str, tasks: list[Row], question: str | None) -> None:
    people = {p for _, _, owner, r in tasks for p in (owner, r)}
    assert not people & ADDED, (frame_text, tasks)
    names = ("Nguyễn", "Trần", "María", "Jan van", "Rhys", "Omar", "Thi Lan")
    assert not any(n in (question or "") for n in names), (frame_text, question)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(_WORDS), st.sampled_from(_DEFAULT_FORMS))
def test_common_words_never_name_a_colleague_default(word: str, form: str) -> None:
    text = form.format(w=word)
    frame = _default(text)
    _nobody_added(
        text, [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks], frame.question
    )


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(_WORDS), st.sampled_from(_HARBOUR_FORMS))
def test_common_words_never_name_a_colleague_harbour(word: str, form: str) -> None:
    text = form.format(w=word)
    frame = _harbour(text)
    _nobody_added(
        text, [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks], frame.question
    )


async def test_end_to_end_no_colleagues_paper_moves() -> None:
    run = await run_instruction(
        default_with_many_part_names(), "zhang", "Could you photocopy this contract for Wang?"
    )
    trace = run.stm.trace
    moved = {r.action.item for r in trace.actions() if isinstance(r.action, SendQR)}
    assert moved, trace.summary
    assert all(i.endswith(":zhang") for i in moved), (moved, trace.summary)
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert not contacts & ADDED, trace.summary
