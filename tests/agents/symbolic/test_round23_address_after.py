"""Blind rounds 23 and 24, class 3 (part): a send-out service's destination described first,
then named after a comma as an address in full ("post the logbook off to the customer
please, Mrs Patel at 14 Elm Road"): the address is where it goes, never a colleague to find.
On sentences of our own against a dealership no sentence was written for (the rounds' office
and sentences were never read)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dealership import dealership
from helpers.reading import frame_reader

_frame = frame_reader(dealership, "gary")


@pytest.mark.parametrize(
    "text",
    [
        "post the logbook off to the customer please, Mrs Patel at 14 Elm Road",
        "post the logbook to the customer, Mrs Patel at 14 Elm Road",
        "could you post my logbook to the buyer, Mr Okoro at 3 Mill Lane",
    ],
)
def test_the_address_after_the_comma_is_where_it_goes(text: str) -> None:
    [task] = _frame(text).tasks
    assert (task.kind, task.item, task.owner) == ("heat", "logbook", "gary")
    assert task.destination is not None and " at " in task.destination
    assert task.destination[0].isupper(), task.destination


@pytest.mark.parametrize(
    "text",
    [
        "post the logbook to the customer please",
        "post the logbook to the customer please, Priya wants it today",
    ],
)
def test_no_address_after_a_role_asks_where(text: str) -> None:
    # since fix129e a role alone ("the customer") says whom, never where: the post asks
    frame = _frame(text)
    assert not frame.tasks, frame
    assert frame.question is not None and frame.question.startswith("Where should I post"), frame


def test_a_negation_moves_nothing() -> None:
    assert _frame("don't post the logbook to the customer, Mrs Patel at 14 Elm Road").tasks == []


async def test_the_logbook_is_posted_to_the_address() -> None:
    run = await run_instruction(
        dealership(),
        "gary",
        "post the logbook off to the customer please, Mrs Patel at 14 Elm Road",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "Mrs Patel at 14 Elm Road" in run.stm.trace.summary
