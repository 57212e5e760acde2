"""Blind rounds 23 and 24, class 3 (part): a thing told to go "on charge", "on to charge" by a
verb that is no errand ("stick", "chuck") goes to the office's service that word asks for,
not to an unknown place. On sentences of our own against a dealership no sentence was written
for (the rounds' office and sentences were never read)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dealership import dealership
from helpers.reading import frame_reader

_frame = frame_reader(dealership, "gary")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can you stick my jump pack on charge, its flat as a pancake",
        "can you put my jump pack on to charge",
        "chuck my jump pack on charge please",
    ],
)
def test_on_a_services_word_asks_for_that_service(text: str) -> None:
    assert _tasks(text) == [("heat", "jump_pack", "gary", "gary")]


def test_a_place_the_office_does_not_know_is_still_asked() -> None:
    frame = _frame("stick my jump pack on the shelf")
    assert frame.tasks == []
    assert frame.question is not None and "not sure what to do" in frame.question


@pytest.mark.parametrize(
    "text", ["stick my jump pack on charge? no wait, it's fine", "is my jump pack on charge?"]
)
def test_a_withdrawal_or_a_question_moves_nothing(text: str) -> None:
    assert _tasks(text) == []


async def test_the_jump_pack_goes_on_charge() -> None:
    run = await run_instruction(dealership(), "gary", "can you stick my jump pack on charge")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "send_qr" in run.actions, run.actions
