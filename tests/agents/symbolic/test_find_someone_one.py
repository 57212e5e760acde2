"""Blind rounds 40 to 42 (fixer B, class 4), on sentences of our own against the default office:
"find" takes whom the thing is for before it, as "get" does: "he left his stapler at home,
could you find him one?" is anyone's stapler for him, not his own taken from him to the
requester. "find Zhang's stapler" is still Zhang's, "find me a stapler" still mine."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "Zhang's desk is a mess and he left his stapler at home. Could you find him one?",
        "Zhang left his stapler at home. Could you find him one?",
        "Could you find Zhang a stapler?",
        "find Zhang Wei a stapler please",
        # near-miss: "get" read so before
        "Zhang left his stapler at home. Could you get him one?",
    ],
)
def test_find_someone_one_is_one_for_them(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", "stapler", None, "zhang")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("find Zhang's stapler", [("transfer", "stapler", "zhang", "lee")]),
        ("find me a stapler", [("transfer", "stapler", None, "lee")]),
        ("find Zhang and give him my stapler", [("transfer", "stapler", "lee", "zhang")]),
    ],
)
def test_find_keeps_whose_and_me(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected
