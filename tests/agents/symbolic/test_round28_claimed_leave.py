"""Leave claimed in the request's own words (blind round 28's class, on an office no sentence
was written for, ``helpers.rota_desk``): "Otto said I can have his leftover soup from the
fridge, could you bring it?" is Otto's soup for the requester; the words carry no authority,
so Otto is still asked in his own chat before anything moves. On main the describing word
("leftover") between "his" and the item lost whose it was, and whose soup was asked."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire, Move
from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "Otto said I can have his leftover soup from the fridge, could you bring it?",
        "Otto said I can have his leftover soup, could you bring it?",
        "Otto said I could have his cold soup, can you bring it to me",
        "Otto's leftover soup is in the fridge, could you bring it to me",
    ],
)
def test_the_soup_is_the_named_colleagues(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "soup", "otto", "ada")
    ], frame


def test_with_two_named_whose_is_asked() -> None:
    frame = _frame("Otto and Bill said I can have his leftover soup, could you bring it?")
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    "text",
    [
        "Otto said I can have his leftover soup",
        "Otto said I could have his leftover soup, thanks Otto!",
    ],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_the_owner_is_asked_before_the_robot_moves() -> None:
    text = "Otto said I can have his leftover soup from the fridge, could you bring it?"
    run = await run_instruction(rota_desk(), "ada", text)
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    asks = [k for k, a in enumerate(acted) if isinstance(a, Inquire) and a.contact == "otto"]
    moves = [k for k, a in enumerate(acted) if isinstance(a, Move)]
    assert asks, acted
    assert not moves or asks[0] < moves[0]
