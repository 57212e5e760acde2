"""A thing said to be wanted with a colleague ("my stapler should go to Lee, he's doing the
notes", "Zhang's book has to go to Lee", "my stapler is for Lee") is a delivery asked for
(class 63f-2: read as a statement, "Noted. I did nothing."); a colleague's thing is handed over
only with its owner's yes, as for any request. Where it should be ("my stapler should be in my
drawer"), what happened ("my stapler went to Wang yesterday") and what it is for ("my stapler
is for stapling") are read as before: nothing moves."""

from __future__ import annotations

import pytest
from _offices import parser


def _frame(text: str, who: str = "chen"):  # type: ignore[no-untyped-def]
    return parser("default").parse(text, who)


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("my stapler should go to Lee, he's doing the notes.", ("stapler", "chen", "lee")),
        ("my stapler must go over to Yang Lei", ("stapler", "chen", "yang")),
        ("Wang's stapler should go back to Lee", ("stapler", "wang", "lee")),
        ("Zhang's book has to go to Lee", ("book", "zhang", "lee")),
        ("Zhang's book has to go to Lee, she's reading it", ("book", "zhang", "lee")),
        ("my stapler is for Lee", ("stapler", "chen", "lee")),
        ("my stapler needs to go to Wang", ("stapler", "chen", "wang")),
    ],
)
def test_a_thing_that_should_go_to_a_colleague_is_delivered(
    text: str, task: tuple[str, str, str]
) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [("transfer", *task)], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    [
        "my stapler should be in my drawer",
        "my stapler went to Wang yesterday",
        "my stapler is for stapling",
        "the stapler has to be in the cupboard",
    ],
)
def test_where_it_should_be_or_went_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
