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


@pytest.mark.parametrize(
    "text",
    [
        # a greeting or a notice phrase left beside a statement says nothing to act on
        "hi, the printer is fixed",
        "no need to do anything, just letting you know the printer is fixed",
        "just so you know, Zhang is out today",
        "heads up: the printer is out of paper",
        # a hedged wish, with its contraction
        "it'd be nice if the coffee were stronger",
        "it'd be great if the printer were faster",
    ],
)
def test_a_message_that_asks_for_nothing_is_answered_in_words(text: str) -> None:
    frame = office_parser("default").parse(text, "wang")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("hi, can you bring me a stapler", ("transfer", "stapler")),
        ("just so you know I need a stapler, can you bring me one", ("transfer", "stapler")),
    ],
)
def test_a_request_after_a_greeting_or_notice_is_still_a_request(
    text: str, wanted: tuple[str, str]
) -> None:
    frame = office_parser("default").parse(text, "wang")
    assert [(t.kind, t.item) for t in frame.tasks] == [wanted]
