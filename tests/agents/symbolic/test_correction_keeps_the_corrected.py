"""A correction keeps only the corrected thing: "bring me the stapler. no wait sorry, a pen.
the stapler can wait" had fetched both (the chain "no wait sorry" read as a withdrawal, and
"the stapler can wait" left the stapler asked), and "bring me Wang's stapler no Zhang's" both
owners' staplers. More words of correcting after a correction's mark are part of it
(``screen.correction``), a "no" between two owners' "'s" with no pause corrects the owner, a
thing that opens its sentence and "can wait" is put off (``frames._rejected_items``), and a
correction that says "also" adds the thing, replacing nothing."""

from __future__ import annotations

import pytest
from _offices import understood_tasks

_STAPLER = ("transfer", "stapler", None, "lee")
_PEN = ("transfer", "pen", None, "lee")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me the stapler. no wait sorry, a pen. the stapler can wait", [_PEN]),
        ("bring me the stapler. no wait sorry, a pen", [_PEN]),
        ("bring me the stapler and a pen. the stapler can wait", [_PEN]),
        ("bring me Wang's stapler no Zhang's", [("transfer", "stapler", "zhang", "lee")]),
        ("bring me a stapler. no wait, also a pen", [_STAPLER, _PEN]),
    ],
)
def test_the_correction_keeps_only_what_it_says(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert understood_tasks("default", "lee", text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me a stapler, no rush", [_STAPLER]),
        ("bring me a stapler and a pen", [_STAPLER, _PEN]),
        ("bring me a stapler, it can wait", [_STAPLER]),
        ("bring me the stapler. no wait, a pen", [_PEN]),
        ("bring me Wang's stapler, no, Zhang's", [("transfer", "stapler", "zhang", "lee")]),
    ],
)
def test_neighbours_read_as_before(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert understood_tasks("default", "lee", text) == expected
