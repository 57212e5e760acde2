"""A third person's pronoun as the subject of a need is not the speaker
(``screen.pronoun_subject``): with nobody named before it, "she needs the umbrella" asks whom
"she" means (before: the umbrella was handed to the speaker); with one colleague named before
("Rose is soaked, she needs the umbrella") it is that colleague's need, restated and asked as
"Rose needs the umbrella" is; the answer to the question names whose need it is. On the
dataset's default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_harbour = frame_reader(harbour_office, "pat")
_default = frame_reader(default_office, "zhang")
_harbour_answered = answered_reader(harbour_office, "pat")
_default_answered = answered_reader(default_office, "zhang")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "pronoun"),
    [
        # the class's analogues
        ("harbour", "she needs the umbrella", "she"),
        ("harbour", "he needs a ruler", "he"),
        # variants of our own: other pronouns, need phrases, things, offices
        ("harbour", "they need a calculator", "they"),
        ("harbour", "she could use a highlighter for the meeting", "she"),
        ("default", "he needs scissors", "he"),
        ("default", "she's after a stapler", "she"),
        ("default", "she needs a stapler, can you bring one", "she"),
    ],
)
def test_a_pronoun_with_nobody_named_is_asked_about(office: str, text: str, pronoun: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None and f"by '{pronoun}'" in frame.question, frame.question


@pytest.mark.parametrize(
    ("office", "text", "question"),
    [
        ("harbour", "Rose is soaked, she needs the umbrella", "an umbrella to Rose Adeyemi"),
        ("harbour", "Mark is working late, he needs a calculator", "a calculator to Mark"),
        ("default", "Lee is cold, he needs a coffee", "coffee for Lee Ming"),
        ("default", "Chen's cold, they need a coffee", "coffee for Chen Jie"),
    ],
)
def test_one_colleague_named_before_is_whom_it_means(office: str, text: str, question: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None and frame.question.startswith("Shall I"), frame.question
    assert question in frame.question, frame.question


def test_several_named_before_and_nothing_asked_asks_which() -> None:
    frame = _harbour("Rose and Mark are here, she needs the umbrella")
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None, frame.question
    assert "Rose Adeyemi" in frame.question and "Mark Lindqvist" in frame.question


@pytest.mark.parametrize(
    ("office", "text", "answers", "item", "recipient"),
    [
        ("harbour", "she needs the umbrella", ["Rose Adeyemi.", "yes"], "umbrella", "rose"),
        ("harbour", "he needs a ruler", ["Mark"], None, None),
        ("harbour", "he needs a ruler", ["Mark", "yes"], "ruler", "mark"),
        ("harbour", "they need a calculator", ["Grace.", "yes"], "calculator", "grace"),
        ("harbour", "she needs the umbrella", ["Me."], "umbrella", "pat"),
        ("default", "he needs scissors", ["Lee", "yes"], "scissors", "lee"),
        (
            "harbour",
            "Rose and Mark are here, she needs the umbrella",
            ["Rose", "yes"],
            "umbrella",
            "rose",
        ),
    ],
)
def test_the_answer_names_whose_need_it_is(
    office: str, text: str, answers: list[str], item: str | None, recipient: str | None
) -> None:
    read = _harbour_answered if office == "harbour" else _default_answered
    frame = read(text, answers)
    if item is None:  # named, not yet agreed: restated and asked first
        assert frame.tasks == [], _tasks(frame)
        assert frame.question is not None and frame.question.startswith("Shall I"), frame.question
        return
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)], _tasks(frame)


@pytest.mark.parametrize(
    ("office", "text", "expected"),
    [
        # must not change: the speaker's own need, a pronoun in a condition, a pronoun that
        # gives the reason for a request to someone named
        ("harbour", "I need the umbrella", [("transfer", "umbrella", "pat")]),
        ("harbour", "bring me the umbrella if she needs it", [("transfer", "umbrella", "pat")]),
        ("harbour", "take Mark's ruler to Grace, she needs it", [("transfer", "ruler", "grace")]),
        ("default", "I need scissors", [("transfer", "scissors", "zhang")]),
    ],
)
def test_neighbours_keep_their_reading(
    office: str, text: str, expected: list[tuple[str, str, str]]
) -> None:
    frame = _read(office, text)
    assert _tasks(frame) == expected, (frame.question, frame.decline)
