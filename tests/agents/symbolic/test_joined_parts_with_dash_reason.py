"""Two requests joined by ", and" where the second carries a reason after a dash ("take my
stapler to Zhang, and bring me Chen's scissors - mine are blunt"): both hand-overs are done,
the reason is a statement beside the second. Pinned on the default office and Harbour, with the
dash written as a hyphen, an en dash or two hyphens; a reason alone asks nothing."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "take my stapler to Zhang, and bring me Chen's scissors - mine are blunt",
        "take my stapler to Zhang, and bring me Chen's scissors – mine are blunt",
        "Take my stapler over to Zhang, and grab me Chen's scissors -- mine are useless",
    ],
)
def test_both_parts_are_done_default(text: str) -> None:
    assert tasks_of("default", text, "hu") == [
        ("transfer", "stapler", "hu", "zhang"),
        ("transfer", "scissors", "chen", "hu"),
    ]


def test_both_parts_are_done_with_another_pair_default() -> None:
    text = "give my pen to Lee, and fetch me Dang's data cable - mine is broken"
    assert tasks_of("default", text, "hu") == [
        ("transfer", "pen", "hu", "lee"),
        ("transfer", "data_cable", "dang", "hu"),
    ]


def test_both_parts_are_done_harbour() -> None:
    text = "take my ruler to Rose, and bring me Will's calculator - mine is broken"
    assert tasks_of("harbour", text, "mark") == [
        ("transfer", "ruler", "mark", "rose"),
        ("transfer", "calculator", "will", "mark"),
    ]


def test_the_reason_alone_asks_for_nothing() -> None:
    frame = parser("default").parse("mine are blunt", "hu")
    assert frame.tasks == [] and frame.question is None, frame
