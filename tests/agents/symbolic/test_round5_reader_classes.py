"""Blind round 5's reader classes, by mechanism, on our own sentences (the round's sentences
were never read): a correction that names what is wanted and rejects what is not ("..., sorry,
a pen, not the stapler") leaves only what is wanted. Only what was asked for moves."""

from __future__ import annotations

import pytest
from _offices import parser as office_parser


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("bring me a stapler, sorry, scissors, not the stapler", ("scissors", None)),
        (
            "can you bring me Zhang's stapler, sorry, his scissors, not the stapler",
            ("scissors", "zhang"),
        ),
        ("bring me a stapler - sorry, a pen, not a stapler", ("pen", None)),
        ("get me scissors, no wait, a stapler not scissors", ("stapler", None)),
        ("bring me a stapler, not the scissors", ("stapler", None)),
    ],
)
def test_a_rejected_item_is_not_fetched(text: str, wanted: tuple[str, str | None]) -> None:
    frame = office_parser("default").parse(text, "wang")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", *wanted, "wang")
    ]


@pytest.mark.parametrize("text", ["not the stapler", "bring me anything but not the stapler"])
def test_a_rejected_item_alone_is_asked_about_never_fetched(text: str) -> None:
    frame = office_parser("default").parse(text, "wang")
    assert frame.tasks == [] and frame.question
