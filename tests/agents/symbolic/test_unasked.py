"""A message none of whose pieces asks for anything (no request wording, no question mark,
no "pls", not a request said short with the thing first) is restated and asked before
anything moves: "Chen and the scissors again" is no request for Chen's scissors. In a blind
round a sentence that only told ("Drew up tomorrow's interview list. It's miles longer than
last week's") forwarded a colleague's file. A request said short ("stapler", "my lunch from
the fridge", "Wang's stapler", "two coffees") and every request with its wording are read as
before."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire, Move
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE


def _frame(text: str):  # type: ignore[no-untyped-def]
    return parser("default").parse(text, "lee")


@pytest.mark.parametrize(
    ("text", "question"),
    [
        ("Wang stapler", "Shall I bring Wang Fang's stapler to you?"),
        ("Zhang the stapler", "Shall I bring Zhang Wei's stapler to you?"),
        ("Chen and the scissors again", "Shall I bring Chen Jie's scissors to you?"),
        ("Zhang book yesterday", "Shall I bring Zhang Wei's book to you?"),
    ],
)
def test_nothing_asked_is_restated_and_asked_first(text: str, question: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question == question, frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("stapler", ("transfer", "stapler", None)),
        ("my lunch from the fridge", ("transfer", "lunch", "lee")),
        ("Wang's stapler", ("transfer", "stapler", "wang")),
        ("two coffees", ("produce", "coffee", None)),
        ("a big stapler on my desk", ("transfer", "stapler", None)),
        ("stapler pls", ("transfer", "stapler", None)),
        ("Wang stapler asap", ("transfer", "stapler", "wang")),
        ("bring me a stapler", ("transfer", "stapler", None)),
        ("can I have Wang's stapler", ("transfer", "stapler", "wang")),
        ("i need a stapler", ("transfer", "stapler", None)),
    ],
)
def test_a_request_said_short_or_with_its_wording_is_read_as_before(
    text: str, task: tuple[str, str, str | None]
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [task], frame


async def test_end_to_end_the_requester_is_asked_before_anything_moves() -> None:
    run = await run_instruction(load_office(DEFAULT_FILE), "lee", "Chen and the scissors again")
    actions = [r.action for r in run.stm.trace.actions()]
    first = next(a for a in actions if isinstance(a, Inquire | Move))
    assert isinstance(first, Inquire) and first.contact == "lee", run.stm.trace.summary
