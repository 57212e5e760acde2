"""A container or measure word ("a box", "a pack") asked for right after a statement that
named an item is a quantity of that item, also when the word is part of another of the
office's names ("lunch box"): only a whole name of the office is that thing (issue 23)."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I ran out of paper. Could you bring me a box?", "paper"),  # "box" of "lunch box"
        ("we're out of wipes. grab me a pack please", "wipes"),
    ],
)
def test_a_container_after_a_statement_is_that_item(text: str, item: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", item, None, "lee")]


def test_a_whole_name_of_the_office_is_still_its_own_thing() -> None:
    assert tasks_of("default", "I ran out of paper. Could you bring me a pen?", "lee") == [
        ("transfer", "pen", None, "lee")
    ]
