"""A reason opened by "as" after a request ("print my report and give it to Mao as he prefers
it on paper", fix186a class 1): "as" with a subject pronoun and a word after it opens a reason
clause like "because" (``reading._objects``), so a format or medium said there ("on paper",
"paper") is how the product is wanted, never a second thing fetched for the recipient. The
"as" of a manner or a comparison ("as soon as you can", "as well as a pen") reads as before."""

from __future__ import annotations

import pytest
from _offices import understood_tasks


@pytest.mark.parametrize(
    "text",
    [
        "could you print my report and hand it to Manager Mao as he prefers it on paper",
        "print my report and give it to Mao as he likes it on paper",
        "print my report and give it to Mao, as he prefers paper",
        "print my report and give it to Mao because he prefers it on paper",  # as before
        "could you print my report and hand it to Manager Mao? he prefers it on paper",
    ],
)
def test_a_format_in_a_reason_is_no_second_thing(text: str) -> None:
    assert understood_tasks("default", "lee", text) == [("print", "file", "lee", "mao")]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # must not change: the thing itself asked, the "as" of a comparison or of a time
        ("give Mao the paper as he needs it", [("transfer", "paper", None, "mao")]),
        (
            "bring me Mao's paper as well as a pen",
            [("transfer", "paper", "mao", "lee"), ("transfer", "pen", None, "lee")],
        ),
        (
            "print my report and give it to Mao as soon as you can",
            [("print", "file", "lee", "mao")],
        ),
    ],
)
def test_other_as_reads_as_before(text: str, tasks: list[tuple[str, str, str | None, str]]) -> None:
    assert understood_tasks("default", "lee", text) == tasks
