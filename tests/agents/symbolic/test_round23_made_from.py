"""Blind rounds 23 and 24, class 3 (part): a product asked for whose operation makes it from a
physical item the request does not say ("get a spare key cut for my car": cut from a car
key; "plates pressing, reg is on the job card": pressed from a job card) is made from the
requester's one such item. On sentences of our own against a dealership no sentence was
written for (the rounds' office and sentences were never read)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dealership import dealership
from helpers.reading import frame_reader

_frame = frame_reader(dealership, "gary")


def _tasks(text: str, who: str = "gary") -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text, who).tasks]


@pytest.mark.parametrize(
    ("text", "source"),
    [
        ("Could you get a spare key cut for my car? The wife keeps pinching mine.", "car_key"),
        ("get a spare key cut", "car_key"),
        ("cut a spare key from my car key", "car_key"),
        ("need a set of plates pressing for the fiesta, reg is on the job card", "job_card"),
        ("can you get me a number plate", "job_card"),
    ],
)
def test_a_product_is_made_from_my_one_input(text: str, source: str) -> None:
    assert _tasks(text) == [("copy", source, "gary", "gary")]


def test_an_input_the_clause_names_is_that_one() -> None:
    assert _tasks("cut a spare key from Priya's car key") == [("copy", "car_key", "priya", "gary")]


def test_with_no_input_of_mine_it_is_still_asked() -> None:
    """Tom owns no car key: nobody else's is taken."""
    frame = _frame("Could you get a spare key cut for my car?", "tom")
    assert frame.tasks == []
    assert frame.question is not None


@pytest.mark.parametrize(
    "text",
    ["thanks for cutting the spare key", "don't cut a spare key", "is the spare key cut yet?"],
)
def test_thanks_a_negation_or_a_question_moves_nothing(text: str) -> None:
    assert _tasks(text) == []


async def test_the_spare_key_is_cut_from_the_requesters_key() -> None:
    run = await run_instruction(dealership(), "gary", "Could you get a spare key cut for my car?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    # main asked "what do you need?" and moved nothing
    assert "send_qr" in run.actions, run.actions
