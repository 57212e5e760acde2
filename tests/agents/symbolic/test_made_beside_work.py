"""Blind rounds 40 to 42 (fixer B, class 1), on sentences of our own against the default office:
a thing a service makes from nothing (its coffee) asked for beside work on an item, as the
requester's own wish ("print my slides, and I'd like a cappuccino too") or as a thing said to
be wanted besides ("..., and a coffee for me too if the machine's working"), is a request of
its own: the print and the coffee made and brought. It asked what to do with the coffee, as if
the print had to act on it. Without a word that says it is wanted besides ("print my slides
and a coffee"), what to do with the coffee is still asked; a clause that hands things over
keeps its coordinated objects."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

_PRINT = ("print", "file", "lee", "lee")
_COPY = ("copy", "document", "lee", "lee")
_COFFEE_ME = ("produce", "coffee", None, "lee")
_COFFEE_ZHANG = ("produce", "coffee", None, "zhang")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Print my slides for me, and I'd like a cappuccino too.", [_PRINT, _COFFEE_ME]),
        ("Print my slides and I'd like a coffee", [_PRINT, _COFFEE_ME]),
        ("Print my slides and I would like a coffee please", [_PRINT, _COFFEE_ME]),
        ("print my handout, and I would also like a cappuccino", [_PRINT, _COFFEE_ME]),
        ("Copy my contract, and a coffee for me too if the machine's working", [_COPY, _COFFEE_ME]),
        ("Print my slides, and a coffee for me too", [_PRINT, _COFFEE_ME]),
        ("photocopy my contract and I want a coffee too", [_COPY, _COFFEE_ME]),
        ("Print my slides and a coffee for Zhang too", [_PRINT, _COFFEE_ZHANG]),
        ("print my slides, and a coffee as well please", [_PRINT, _COFFEE_ME]),
    ],
)
def test_a_made_product_beside_work_on_an_item_is_a_request_of_its_own(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected


@pytest.mark.parametrize(
    "text",
    ["Print my slides and a coffee", "print my slides and a coffee for Zhang"],
)
def test_a_made_product_said_as_the_works_object_is_still_asked_about(text: str) -> None:
    """Nothing says the coffee is asked for besides: asked first (the whole restated)."""
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is not None
    assert "coffee" in frame.question


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Print my slides", [_PRINT]),
        ("I'd like a cappuccino.", [_COFFEE_ME]),
        ("Print my slides. I'd like a coffee too.", [_PRINT, _COFFEE_ME]),
        ("print my report and a copy for Zhang", [("print", "file", "lee", "zhang")]),
        (
            "Bring me the stapler, and a coffee for Zhang",
            [("transfer", "stapler", None, "lee"), _COFFEE_ZHANG],
        ),
        ("Print my slides and I need them by noon", [_PRINT]),
    ],
)
def test_near_misses_keep_their_reading(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected
