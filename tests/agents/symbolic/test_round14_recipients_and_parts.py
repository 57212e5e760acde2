"""Blind round 14's reader classes about who receives and which parts a request has, on
sentences of our own against a ceramics studio's design office no sentence was written for
(``helpers.kilnworks``; the round's own office and sentences were never read): a title alias
with its article ("the Provost"), a person's own place as where they receive ("leave one at
her desk"), a colleague's item asked for by "theirs", a part of a request that cannot be
resolved, and "for her" after a printed product."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import TaskFrame
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.kilnworks import kilnworks


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(kilnworks())


def _frame(text: str, who: str = "kit") -> TaskFrame:
    return _parser().parse(text, who)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]


# -- 1. a title alias with its article is the person --------------------------------------


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("print my agenda and give it to the Provost", [("print", "agenda", "oona", None)]),
        ("print my agenda for the Provost", [("print", "agenda", "oona", None)]),
        ("take my report to the provost please", [("transfer", "report", "oona", None)]),
        ("get the Provost to sign my report", [("sign", "report", "kit", "oona")]),
        ("bring me the Provost's calculator", [("transfer", "calculator", "kit", None)]),
    ],
)
def test_a_title_declared_with_its_article_names_the_person(
    text: str, tasks: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    """ "the Provost" is declared for Oona Pike: written with its article it is her, as
    recipient, signer or owner; never "Do you mean Oona Pike, or the provost?"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


def test_the_owner_named_by_a_title_alias_is_the_owner() -> None:
    frame = _frame("bring me the Provost's calculator")
    assert [t.owner for t in frame.tasks] == ["oona"]


@pytest.mark.parametrize(
    "text", ["print my agenda and give it to the Provost", "take my report to the Provost"]
)
def test_the_guard_knows_the_title_alias_as_the_recipient(text: str) -> None:
    assert named_recipients(kilnworks(), memory("kit", text)) == {"oona"}


@pytest.mark.parametrize(
    "text", ["what does a provost do?", "is there a provost here?", "who is the provost?"]
)
def test_a_question_about_the_title_moves_nothing(text: str) -> None:
    """Near-miss: a question naming the title is still a question."""
    assert _frame(text).tasks == []


async def test_a_printout_for_the_title_alias_is_handed_to_her() -> None:
    run = await run_instruction(kilnworks(), "kit", "print my agenda and give it to the Provost")
    handed = [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and not r.refused
    ]
    assert ("oona", "collect") in handed
    assert not [r for r in run.stm.trace.actions() if r.refused]
