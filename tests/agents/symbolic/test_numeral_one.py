""" "one for X" after a thing for the speaker is a second one, also texted as "1"
(``reading.numeral_one``): "coffee for me and 1 for Wang" makes two coffees, one each, as
"... and one for Wang" does; before, only Wang's was made. The spelled-out forms, a bare
product noun ("brew") as the first conjunct's head, and digits that count or number ("1
sugar", "desk 1") are pinned as they were."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic.reading.numeral_one import numeral_ones


@pytest.mark.parametrize(
    ("name", "who", "text", "tasks"),
    [
        # the texted "1": was only the second person's product
        (
            "default",
            "lin",
            "coffee for me and 1 for Wang",
            [("produce", "coffee", None, "lin"), ("produce", "coffee", None, "wang")],
        ),
        (
            "default",
            "lin",
            "a water for me & 1 for Zhang",
            [("produce", "water", None, "lin"), ("produce", "water", None, "zhang")],
        ),
        (
            "harbour",
            "will",
            "tea for me and 1 for Rose",
            [("produce", "tea", None, "will"), ("produce", "tea", None, "rose")],
        ),
        # the class's analogues, spelled out (already two products on main; pinned)
        (
            "default",
            "lin",
            "coffee for me and one for Wang if you're going past the machine",
            [("produce", "coffee", None, "lin"), ("produce", "coffee", None, "wang")],
        ),
        (
            "default",
            "lin",
            "a water for me and one for Zhang",
            [("produce", "water", None, "lin"), ("produce", "water", None, "zhang")],
        ),
        (
            "harbour",
            "will",
            "brew for me and one for Mark if ur going past the urn",
            [("produce", "tea", None, "will"), ("produce", "tea", None, "mark")],
        ),
        # must not change: "one sugar" is no second coffee
        ("default", "lin", "a coffee for Wang and 1 sugar", [("produce", "coffee", None, "wang")]),
        (
            "default",
            "lin",
            "a coffee for Wang and one sugar",
            [("produce", "coffee", None, "wang")],
        ),
    ],
)
def test_one_for_another_after_the_speakers_is_a_second(
    name: str, who: str, text: str, tasks: list[tuple[str, str, None, str]]
) -> None:
    assert tasks_of(name, text, who) == tasks


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("coffee for me and 1 for Wang", "coffee for me and one for Wang"),
        ("tea & 1 more", "tea & one more"),
        ("bring a pen to desk 1 for Wang", "bring a pen to desk 1 for Wang"),
        ("a coffee and 1 sugar", "a coffee and 1 sugar"),
        ("swap them 1 for 1 and 1 for Wang", "swap them 1 for 1 and 1 for Wang"),
    ],
)
def test_numeral_ones(text: str, read: str) -> None:
    assert numeral_ones(text) == read
