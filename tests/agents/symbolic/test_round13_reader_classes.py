"""Blind round 13's reader classes, by mechanism, on sentences of our own against a small
county records archive no sentence was written for (``helpers.archive``): an operation whose
display name reads like a verb phrase ("print box labels", verb "tag"), a badge press that
makes visitor passes from nothing, a reel reader that digitises a glass slide into an
electronic scan, a mounting press that mounts a chart (the round's own office and sentences
were never read)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import TaskFrame
from helpers.archive import archive


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(archive())


def _frame(text: str, who: str = "ines") -> TaskFrame:
    return _parser().parse(text, who)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.operation, t.recipient) for t in frame.tasks]


# -- 1. an operation's display name is no verb of a request ---------------------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("print my document file, and also bring me a step ladder", "ines"),
        ("print my box list and bring me a kick step", "ines"),
        ("could you print my document for Priya? and a step ladder for me", "priya"),
    ],
)
def test_a_plain_print_is_one_print_not_the_label_run_too(text: str, recipient: str) -> None:
    """ "print" is the printer's verb; the label run whose *name* is "print box labels" is
    asked for by its own verb ("tag") or its product, never by the words of its name: one
    verb phrase, one task."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    prints = [t for t in frame.tasks if t.kind == "print"]
    assert [(t.operation, t.recipient) for t in prints] == [("print", recipient)]
    assert [t.item for t in frame.tasks if t.kind == "transfer"] == ["step_ladder"]


@pytest.mark.parametrize(
    "text",
    ["tag my document", "print my document as box labels", "run off box labels from my box list"],
)
def test_the_label_run_is_still_asked_for_by_its_verb_or_product(text: str) -> None:
    assert _tasks(_frame(text)) == [("print", "doc_file", "tag", "ines")]


def test_both_operations_said_are_both_done() -> None:
    """Near-miss: the printer's verb and the label run's own verb, each said, are two tasks."""
    frame = _frame("print my box list, and tag it too")
    assert [t.operation for t in frame.tasks] == ["print", "tag"]
