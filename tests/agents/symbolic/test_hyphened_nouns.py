"""A verb and its particle hyphened after a determiner and before a noun name a thing or an
event ("a pen for the warm-up drill"), never the work asked (``reading.hyphened_nouns``): the
default office heats things, and read "warm" as heating a pen, declined. A compound the office
names, or one with no noun after it ("take the print-out to Mao": the printout made), keeps
its reading."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic.reading.hyphened_nouns import hyphened_nouns


@pytest.mark.parametrize(
    "text",
    [
        "Could you bring me a pen for the warm-up drill?",
        "can I get a stapler for the warm-up session pls",
        "bring me a pen for the sign-off meeting",
    ],
)
def test_the_thing_is_brought_for_the_event(text: str) -> None:
    tasks = tasks_of("default", text, "lee")
    assert [(k, i, r) for k, i, _, r in tasks] in (
        [("transfer", "pen", "lee")],
        [("transfer", "stapler", "lee")],
    )


def test_the_print_out_after_printing_is_still_the_printout() -> None:
    tasks = tasks_of("default", "print my file and take the print-out to Mao", "lee")
    assert tasks == [("print", "file", "lee", "mao")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a pen for the warm-up drill", "a pen for the warmup drill"),
        ("take the print-out to Mao", "take the print-out to Mao"),  # no noun after it
        ("the print-out paper", "the print-out paper"),  # the office's word after it
    ],
)
def test_the_rewrite(text: str, expected: str) -> None:
    assert hyphened_nouns(text, frozenset({"paper"})) == expected
