"""Blind rounds 40 to 42 (fixer B, class 2), on sentences of our own against the default office:
"a coffee for me and one for Zhang": "one" after an object, with whom it is for said right
after it, is another of that object for that person; both get one (only Zhang did). A coffee
for one person is still one task."""

from __future__ import annotations

import pytest
from _offices import tasks_of

_COFFEE_ME = ("produce", "coffee", None, "lee")
_COFFEE_ZHANG = ("produce", "coffee", None, "zhang")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "coffee for me and one for Zhang please, he's been here since six",
            [_COFFEE_ME, _COFFEE_ZHANG],
        ),
        ("a coffee for me and one for Zhang please", [_COFFEE_ME, _COFFEE_ZHANG]),
        (
            "bring me a coffee and one for Yang Lei",
            [_COFFEE_ME, ("produce", "coffee", None, "yang")],
        ),
        (
            "bring a stapler for me and one for Zhang",
            [("transfer", "stapler", None, "lee"), ("transfer", "stapler", None, "zhang")],
        ),
    ],
)
def test_one_for_another_person_is_another_of_the_same(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected


@pytest.mark.parametrize(
    "text",
    ["a coffee for Zhang please", "could you make Zhang a coffee"],
)
def test_one_coffee_for_one_person_is_one_task(text: str) -> None:
    assert tasks_of("default", text, "lee") == [_COFFEE_ZHANG]
