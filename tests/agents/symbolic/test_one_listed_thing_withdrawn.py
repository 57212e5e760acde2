"""A withdrawal that names one of a request's listed things withdraws that thing only (fix213b
class 2): "bring me a stapler and a pen. actually forget the stapler" had the whole request
dropped. The request is read without the thing named (``reading.withdrawn_thing``); one naming
nothing ("actually forget it", "never mind") or the request's one thing withdraws it all."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("bring me a stapler and a pen. actually forget the stapler", "pen"),
        ("bring me a stapler and a pen. scratch the pen", "stapler"),
        ("bring me a stapler and a pen, never mind the pen", "stapler"),
        ("bring me Wang's stapler and a pen. actually forget the stapler", "pen"),
        ("bring me a stapler and a pen. actually forget the stapler, I found one", "pen"),
    ],
)
def test_the_other_thing_still_comes(text: str, kept: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", kept, None, "lee")]


def test_a_request_after_the_withdrawal_is_read_too() -> None:
    text = "bring me a stapler and a pen. actually forget the stapler, bring me a coffee instead"
    assert tasks_of("default", text, "lee") == [
        ("transfer", "pen", None, "lee"),
        ("produce", "coffee", None, "lee"),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "bring me a stapler and a pen. actually forget it",
        "bring me a stapler and a pen. never mind",
        "bring me a stapler. actually forget the stapler",
    ],
)
def test_neighbour_naming_nothing_or_the_one_thing_withdraws_all(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and (frame.decline or "").startswith("OK, I've dropped")


def test_neighbour_a_detail_withdraws_nothing() -> None:
    text = "get me a coffee and a pen, and don't worry about the sugar"
    assert tasks_of("default", text, "lee") == [
        ("produce", "coffee", None, "lee"),
        ("transfer", "pen", None, "lee"),
    ]
