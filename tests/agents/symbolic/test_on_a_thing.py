"""A verbless fragment that tells of something on, in or over a thing ("oil on the stapler
again", "glue all over my scissors", "coffee on my keyboard again, ugh") is a remark, told and
answered in words: it had fetched the thing it named, or made the coffee it named (a wrong
physical action in a blind round: "... oil on the velvet AGAIN" fetched a colleague's
fabric). A thing asked for and where to leave it ("the stapler on my desk please", "coffee on
my desk", "coffee in the meeting room"), or with a word that asks, is read as before."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE


def _frame(text: str):  # type: ignore[no-untyped-def]
    return parser("default").parse(text, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "oil on the stapler again",
        "glue all over my scissors",
        "toner all over my notes",
        "coffee on my keyboard again, ugh",
        "water on the floor again",
        "ink on the book again. someone's been eating at my desk",
        "crumbs in my stapler",
    ],
)
def test_something_on_a_thing_is_told_not_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("stapler", ("transfer", "stapler", "lee")),
        ("the stapler on my desk please", ("transfer", "stapler", "lee")),
        ("coffee on my desk", ("produce", "coffee", "lee")),
        ("coffee in the meeting room", ("produce", "coffee", "lee")),
        ("stapler from Wang's desk", ("transfer", "stapler", "lee")),
        ("oil on the stapler again, can you bring me a book", ("transfer", "book", "lee")),
    ],
)
def test_a_thing_asked_for_is_read_as_before(text: str, task: tuple[str, str, str]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task], frame


async def test_end_to_end_a_remark_moves_nothing() -> None:
    run = await run_instruction(load_office(DEFAULT_FILE), "lee", "glue all over my scissors")
    trace = run.stm.trace
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
