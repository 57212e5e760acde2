"""Blind round 14's reader classes, by mechanism, on sentences of our own against a small
youth hostel's back office no sentence was written for (``helpers.hostel``): a post room
that keeps a parcel for anyone and sends parcels out by courier, a kitchen that keeps a
kettle and makes tea, people's step stools, ladders, book carts, storybooks and project
folders (the round's own office and sentences were never read)."""

from __future__ import annotations

import functools
import unicodedata

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import TaskFrame
from helpers.hostel import hostel

Row = tuple[str, str | None, str | None, str | None]


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(hostel())


def _frame(text: str, who: str = "hamid") -> TaskFrame:
    return _parser().parse(text, who)


def _tasks(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 4. "<Name>'s trying ..., take her a stool": the name written with decomposed accents -----


def _decomposed(text: str) -> str:
    return unicodedata.normalize("NFD", text)


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Siân's trying to reach the top shelf, can you take her a step stool?", "sian"),
        (
            _decomposed("Siân's trying to reach the top shelf, can you take her a step stool?"),
            "sian",
        ),
        (_decomposed("Siân’s up on a chair, could you bring her a step stool"), "sian"),
        (_decomposed("Trần Bảo Châu's trying to reach the shelf, take her a ladder pls"), "chau"),
        ("Mei's been trying to reach the top shelf, can you take her a step stool?", "mei"),
        ("Dara's carrying the boxes upstairs, can you take him the book cart", "dara"),
    ],
)
def test_the_one_person_named_before_is_whom_the_pronoun_means(text: str, to: str) -> None:
    """A letter and its combining accent (text pasted in the decomposed form) are one word, so
    "Sia\u0302n's" is Siân's, not "Sia" and "n's"; the one person named is "her"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", to)]


@pytest.mark.parametrize(
    "text",
    [
        _decomposed("Siân and Mei are trying to reach the shelf, can you take her a step stool?"),
        "Mei and Oona are trying to reach the shelf, can you take her a step stool?",
    ],
)
def test_two_people_named_before_the_pronoun_still_ask(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is not None


async def test_a_decomposed_name_is_handed_the_stool_with_no_refusal() -> None:
    text = _decomposed("Siân's trying to reach the top shelf, can you take her a step stool?")
    run = await run_instruction(hostel(), "hamid", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert not [r for r in run.stm.trace.actions() if r.refused]
    stools = {item: who for item, who in run.sim.world.holder.items() if "step_stool" in item}
    assert "sian" in stools.values(), stools
