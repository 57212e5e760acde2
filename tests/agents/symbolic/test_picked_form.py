"""A form said after a paper or a file picks which of the two is meant (fix93e class 2): "the
paper one", "the hard copy", "the printed one" pick the colleague's paper (a hand-over); "the
pdf one", "the electronic one", "the digital copy" pick their electronic file (sent on). Before,
"Wang Fang's file, the paper one" sent the file AND fetched a pack of blank paper, and "Wang
Fang's document, the pdf one" asked whom to pass a file to. The names come from the office's
own signable paper and file types; a paper with no pick, and blank paper picked by another
word, read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")

_WANG_PAPER = [("transfer", "document", "wang", "lee")]
_WANG_FILE = [("send_file", "file", "wang", "lee")]
_MARK_PAPER = [("transfer", "document", "mark", "rose")]
_MARK_FILE = [("send_file", "file", "mark", "rose")]


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("I need Wang Fang's file, the paper one", _WANG_PAPER),
        ("could you get me Wang Fang's file - the hard copy", _WANG_PAPER),
        ("I need Wang's report, the printed one", _WANG_PAPER),
        ("I need Wang Fang's document, the pdf one", _WANG_FILE),
        ("I need Wang Fang's report, the digital copy", _WANG_FILE),
        ("Wang's contract please, the electronic version", _WANG_FILE),
    ],
)
def test_the_pick_decides_in_the_default_office(text: str, expected: object) -> None:
    assert _tasks(_default(text)) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("can you bring me Mark's file, the printed one", _MARK_PAPER),
        ("I need Mark's deck, the physical copy", _MARK_PAPER),
        ("I need Mark's contract, the electronic one", _MARK_FILE),
        ("I need Mark's timesheet, the soft copy", _MARK_FILE),
    ],
)
def test_the_pick_decides_in_harbour(text: str, expected: object) -> None:
    assert _tasks(_harbour(text)) == expected


def test_a_paper_and_a_file_without_a_pick_read_as_before() -> None:
    assert _tasks(_default("I need Wang Fang's document")) == _WANG_PAPER
    assert _tasks(_default("I need Wang Fang's file")) == _WANG_FILE
    assert _tasks(_harbour("I need Mark's contract")) == _MARK_PAPER


def test_blank_paper_picked_by_another_word_is_still_paper() -> None:
    tasks = _tasks(_default("I need some paper, the printer one"))
    assert [(k, i, r) for k, i, _, r in tasks] == [("transfer", "paper", "lee")]


def test_a_head_that_is_another_thing_of_the_office_keeps_its_words() -> None:
    # blank paper is the default office's own thing: "the printed one" picks no document
    tasks = _tasks(_default("I need some paper, the printed one"))
    assert [(k, i, r) for k, i, _, r in tasks] == [("transfer", "paper", "lee")]
