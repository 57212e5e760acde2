"""Blind round 14's speech-act classes, by mechanism, on sentences of our own against a small
photo studio no sentence was written for (``helpers.studio``): what kind of act a message or
a piece of it is (a statement, a question, an aside, a correction, a reason, a withdrawal),
never moving anything on a piece that asks for nothing (the round's own office and sentences
were never read)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import TaskFrame
from helpers.studio import studio


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(studio())


def _frame(text: str, who: str = "lotte") -> TaskFrame:
    return _parser().parse(text, who)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 5. a reason clause is no withdrawal ----------------------------------------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my mug to Kwame, he lent me his last week and his went missing", "kwame"),
        ("take my mug over to Farida - she lent me hers yesterday and hers is lost now", "farida"),
        ("bring my mug to Kwame, Farida lent me hers the other day and it's gone", "kwame"),
        ("take my mug to Kwame, his went missing", "kwame"),
    ],
)
def test_a_reason_told_with_the_request_does_not_withdraw_it(text: str, recipient: str) -> None:
    """What someone did before the asking ("lent me his last week") and what happened to
    their own thing ("his went missing") is why the request is made, not news that it is
    had already: the request is done."""
    frame = _frame(text)
    assert frame.decline is None, frame.decline
    assert frame.question is None, frame.question
    assert _tasks(frame) == [("transfer", "mug", "lotte", recipient)]


@pytest.mark.parametrize(
    "text",
    [
        "take my mug to Kwame, forget it",
        "take my mug to Kwame. actually never mind, Farida already lent me hers",
        "bring me a tape measure - oh wait, Teodor lent me his",
        "bring me a tape measure, cancel that",
    ],
)
def test_a_withdrawal_of_the_request_itself_still_drops_it(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.decline is not None and "dropped" in frame.decline
