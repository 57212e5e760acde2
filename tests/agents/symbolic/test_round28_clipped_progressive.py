"""A statement after the request, its "are" left out, naming someone with "with" (blind
round 28's class, on an office no sentence was written for, ``helpers.rota_desk``): "can you
brew a tea for me? two parcels going out with Otto later" is what is under way, context; the
request's "for me" decides whom the tea is for, never the "with Otto" of the statement."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("can you brew a tea for me? two parcels going out with Otto later", "produce", "tea"),
        ("can you brew a tea for me? van leaving with Otto at five", "produce", "tea"),
        ("print my rota for me, parcels going out with Otto later", "print", "rota"),
        ("print my rota please, Otto heading home early", "print", "rota"),
    ],
)
def test_a_clipped_statement_names_nobody_to_receive(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, "ada")], frame


@pytest.mark.parametrize(
    "text",
    [
        "print my rota. leave it with Otto",
        "print my rota. someone going past could leave it with Otto",
        "print my rota and give it to Otto, he's heading home early",
    ],
)
def test_a_request_to_leave_it_with_someone_still_does(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "rota", "otto")]


@pytest.mark.parametrize(
    "text",
    ["two parcels going out with Otto later", "Otto heading home early, thanks"],
)
def test_the_statement_alone_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []
