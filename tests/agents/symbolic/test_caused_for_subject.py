"""A colleague (or "she"/"he" of the one colleague named before) as the subject of a causative
asked with a modal, "can/could <person> get/have <thing> <participle>" ("could Wang get my
report printed", "can Zhang get a copy of my report made", "Zhang starts tomorrow, can he get
my report printed"): the thing is made for that colleague, who receives it; never the speaker
(fix59f class 1: the ticket was printed and handed to the speaker). The speaker's own
causatives ("can I get a coffee made", "can you get my report printed") still go to the
speaker, "could Wang get me my report printed" has Wang do it for the speaker, and a pronoun
with no one named before it is never resolved to a colleague."""

from __future__ import annotations

import pytest

from assistantx.core.asked_to_have import caused_for
from assistantx.core.office import load_office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import harbour_office
from helpers.reading import answered_reader, frame_reader

_OFFICE = load_office()
_frame = frame_reader(load_office, "lee")
_answered = answered_reader(load_office, "lee")
_harbour = frame_reader(harbour_office, "may")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("could Wang get my report printed", ("print", "file", "lee", "wang")),
        ("can Zhang get a copy of my report made", ("copy", "document", "lee", "zhang")),
        (
            "Zhang starts tomorrow, can he get my report printed",
            ("print", "file", "lee", "zhang"),
        ),
        (
            "Wang starts on the front desk tomorrow, could she have my report printed",
            ("print", "file", "lee", "wang"),
        ),
    ],
)
def test_the_causatives_subject_receives(text: str, task: tuple[str, str, str, str]) -> None:
    frame = _frame(text)
    assert _tasks(frame) == [task], frame


@pytest.mark.parametrize(
    "text",
    ["could Ray get his badge laminated", "Ray's in at 9, could he get his badge laminated"],
)
def test_his_badge_laminated_for_him(text: str) -> None:
    frame = _harbour(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("badge", "ray", "ray")]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("can I get a coffee made", ("produce", "coffee", None, "lee")),
        ("can you get my report printed", ("print", "file", "lee", "lee")),
        ("could Wang get me my report printed", ("print", "file", "lee", "lee")),
        ("Wang starts on the front desk tomorrow, can she get a coffee made", None),
    ],
)
def test_must_not_change(text: str, task: tuple[str, str, str | None, str] | None) -> None:
    frame = _frame(text)
    if task is None:  # unchanged: already read as for Wang
        assert [t.recipient for t in frame.tasks] == ["wang"], frame
    else:
        assert _tasks(frame) == [task], frame


def test_she_with_no_one_named_is_nobody_guessed() -> None:
    frame = _frame("can she get it?")
    assert not frame.tasks and frame.question, frame


def test_the_colleague_named_in_an_appositive_receives() -> None:
    frame = _frame(
        "we've got a new volunteer, Zhang, starting on the front desk tomorrow. "
        "can he get my report printed"
    )
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "lee", "zhang")]


def test_he_with_nobody_named_is_asked_then_answered() -> None:
    frame = _frame("can he get my report printed")
    assert not frame.tasks and frame.question is not None and "'he'" in frame.question, frame
    answered = _answered("can he get my report printed", ["Zhang"])
    assert [(t.kind, t.owner, t.recipient) for t in answered.tasks] == [
        ("print", "lee", "zhang")
    ], answered


def test_she_after_two_colleagues_is_asked_which() -> None:
    frame = _frame("Wang and Zhang start tomorrow, can she get my report printed")
    assert not frame.tasks and frame.question is not None, frame
    assert "Wang Fang" in frame.question and "Zhang Wei" in frame.question


@pytest.mark.parametrize(
    ("before", "after", "expected"),
    [
        ("could", "get my report printed", True),
        ("can", "have his badge laminated", True),
        ("can", "get a copy of my report made", True),
        ("could", "get me one printed", False),  # does it for the requester
        ("could", "get the signed form", False),  # the participle only describes it
        ("could", "get the report to me printed", False),
        ("please", "get my report printed", False),  # no modal: no subject asked
        ("could", "bring my report printed", False),
    ],
)
def test_caused_for(before: str, after: str, expected: bool) -> None:
    assert caused_for(before, after.split()) is expected


def test_the_guard_lets_the_colleague_named_receive() -> None:
    stm = memory("lee", "could Wang get my report printed")
    assert "wang" in named_recipients(_OFFICE, stm)
    stm = memory("lee", "Zhang starts tomorrow, can he get my report printed")
    assert "zhang" in named_recipients(_OFFICE, stm)
