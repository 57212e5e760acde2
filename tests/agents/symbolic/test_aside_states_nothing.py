"""A request aside's own verb makes no statement of the piece it closes (``asides
.without_asides``, read by the speech acts): "bring Wang my stapler, and a coffee for me while
you are at it" dropped the coffee in silence (the piece was read as a statement, context
only, for the "you are" of "while you are at it"; "while you're at it" was read right). A
statement beside a request is still one."""

from __future__ import annotations

from typing import Any

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")

Row = tuple[str, str, str | None, str | None]


def _rows(frame: Any) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "also"),
    [
        ("bring Wang my stapler, and a coffee for me while you are at it", "coffee"),
        ("bring Wang my stapler and some water for me while you are at it", "water"),
    ],
)
def test_default_office_thing_before_an_aside_is_asked(text: str, also: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _rows(frame) == [
        ("transfer", "stapler", "lin", "wang"),
        ("produce", also, None, "lin"),
    ], frame


def test_harbour_thing_before_an_aside_is_asked() -> None:
    frame = _harbour("take my ruler to Mark, and a tea for me while you are at it")
    assert _rows(frame) == [("transfer", "ruler", "may", "mark"), ("produce", "tea", None, "may")]


@pytest.mark.parametrize(
    "text", ["bring me a stapler, you are a star", "bring me a stapler, Wang is at lunch"]
)
def test_a_statement_beside_a_request_adds_nothing(text: str) -> None:
    assert _rows(_default(text)) == [("transfer", "stapler", None, "lin")]


def test_an_aside_alone_asks_nothing() -> None:
    assert _default("you are at it again").tasks == []
