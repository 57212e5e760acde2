"""After a purpose infinitive ("paper *to write on*", "a book *to read*"), "and" with an
article opens a second thing of the same request, for the same recipient (``_objects``):
the infinitive's clause had swallowed it, and only the first thing was handed over. The
infinitive's own objects ("to sign my contract and letter with") stay its own."""

from __future__ import annotations

import pytest
from _offices import Row as _Row
from _offices import understood_tasks as _tasks


@pytest.mark.parametrize(
    ("name", "who", "text", "done"),
    [
        (
            "default",
            "lee",
            "i need some paper to write on, and a pen",
            [("transfer", "paper", None, "lee"), ("transfer", "pen", None, "lee")],
        ),
        (
            "default",
            "lee",
            "bring me a book to read and a water from the dispenser",
            [("transfer", "book", None, "lee"), ("produce", "water", None, "lee")],
        ),
        (
            "default",
            "lee",
            "bring me a pen to sign my document and a stapler",
            [("transfer", "pen", None, "lee"), ("transfer", "stapler", None, "lee")],
        ),
        # a thing said with its source facility, by the facility's product
        (
            "default",
            "lee",
            "bring me a book to read and a soda from the vending machine",
            [("transfer", "book", None, "lee"), ("produce", "snack", None, "lee")],
        ),
        (
            "harbour",
            "may",
            "bring Bill a notepad to write on and a highlighter",
            [("produce", "notepad", None, "bill"), ("transfer", "highlighter", None, "bill")],
        ),
        # must not change: the infinitive's own object, and no second thing
        (
            "default",
            "lee",
            "bring me a pen to sign my document and my contract with",
            [("transfer", "pen", None, "lee")],
        ),
        ("default", "lee", "bring me a book to read", [("transfer", "book", None, "lee")]),
    ],
)
def test_a_second_thing_after_a_purpose_is_asked_for_too(
    name: str, who: str, text: str, done: list[_Row]
) -> None:
    assert _tasks(name, who, text) == done
