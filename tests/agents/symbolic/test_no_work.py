"""Work said to be lacking ("I have nothing to print", "we've got nothing to scan this week")
is told, never asked: no service runs on the speaker's thing (noticed beside round 166's
class 2; ``reading.no_work``). A tool lacked ("nothing to write with") is still a need, and a
request beside the lack still runs."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("default", "lee", "I have nothing to print"),
        ("default", "lee", "I've got nothing to print today"),
        ("default", "lee", "nothing to print"),
        ("harbour", "bill", "we've got nothing to scan this week"),
    ],
)
def test_no_work_told_moves_nothing(office: str, requester: str, text: str) -> None:
    assert tasks_of(office, text, requester) == []


def test_a_request_beside_it_is_the_only_work() -> None:
    assert tasks_of("harbour", "I have nothing to print, could you scan my document", "bill") == [
        ("copy", "document", "bill", "bill")
    ]


def test_a_tool_lacked_is_still_a_need() -> None:
    assert tasks_of("default", "I have nothing to write with", "lee") == [
        ("transfer", "pen", None, "lee")
    ]
