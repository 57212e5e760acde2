"""A speaker who opens by naming themselves, by an alias (blind round 28's class, on an office
no sentence was written for, ``helpers.rota_desk``: Ada Brennan is also "Bren"): "Bren here,
my ruler is lost, can someone send one over" is a ruler for the requester; on main the name
was read as a party and whom the ruler was for was asked. A colleague's name there is no
introduction."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "Bren here, my ruler is lost and I can't find one, can someone send one over",
        "Bren here, can someone bring me a ruler",
        "Bren here - my ruler's gone, could someone send one over",
        "Ada here, can someone send a ruler over",
        "hi, it's Bren, could someone bring me a ruler",
    ],
)
def test_the_speakers_own_name_introduces_them(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "ruler", "ada")]


def test_a_full_name_introduction_keeps_the_request() -> None:
    frame = _frame("this is Ada Brennan - can you print my rota")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "rota", "ada")]


def test_a_colleagues_name_is_no_introduction() -> None:
    frame = _frame("can you take my ruler to Otto, Bren here")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("ruler", "otto")]


@pytest.mark.parametrize("text", ["Bren here", "Bren here, thanks for the ruler"])
def test_an_introduction_alone_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []
