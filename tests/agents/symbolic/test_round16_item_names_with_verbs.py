"""Item names that hold a verb form or an operation's word are items (blind round 16's class
4; the round's office and sentences were never read). In the newsroom the courier lists "run"
and the trimmer "cut", yet "running sheet" and "cutting mat" are things to print, carry and
hand over; "the Publisher" is the colleague with that alias. On main these were already read
so; the tests keep them so beside the errand reading of "run it over to" (class 2)."""

from __future__ import annotations

import pytest

from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("print my running sheet and give it to the Publisher", ("print", "file", "ines", "bea")),
        ("print the running sheet for the Publisher", ("print", "file", "ines", "bea")),
        ("give my running sheet to the Publisher", ("transfer", "running_sheet", "ines", "bea")),
        (
            "could you run my running sheet over to the Publisher",
            ("transfer", "running_sheet", "ines", "bea"),
        ),
        ("bring the cutting mat to the Publisher", ("transfer", "cutting_mat", None, "bea")),
        ("can you take Mark's cutting mat to Bea", ("transfer", "cutting_mat", "mark", "bea")),
        ("can i borrow a cutting mat", ("transfer", "cutting_mat", None, "ines")),
    ],
)
def test_the_item_is_an_item(text: str, expected: tuple[str, str, str | None, str]) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [expected]
    assert all(t.operation not in ("courier", "trim") for t in frame.tasks)


@pytest.mark.parametrize(
    "text",
    ["thanks for running my running sheet over", "is the cutting mat on Mark's desk?"],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []
