"""A correction mid-message that says a request of its own with "it"/"them"/"that" for its
thing ("take my mug to the kitchenette - no wait, give it to Fang") keeps the thing and its
owner of the request it replaces; only where or to whom it goes is new (blind round 65's
class: the first request was withdrawn with its thing, so "it" was lost or taken for another
thing said after it). "on second thoughts" corrects like "no wait". A correction naming a
thing of its own replaces the thing; one that withdraws moves nothing."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader


@functools.cache
def _office() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_office, "mao")


@pytest.mark.parametrize(
    ("text", "item", "owner", "recipient"),
    [
        (
            "take my mug to the kitchenette - no wait, give it to Fang, she hasn't got a cup "
            "for the meeting",
            "cup",
            "mao",
            "wang",
        ),
        ("take my mug to the kitchenette - no wait, give it to Fang", "cup", "mao", "wang"),
        ("take my stapler to Lee - actually, give it to Zhang", "stapler", "mao", "zhang"),
        ("bring Lee's scissors to me... actually, take them to Wang", "scissors", "lee", "wang"),
        (
            "take my mug to the kitchenette - on second thoughts, give it to Fang",
            "cup",
            "mao",
            "wang",
        ),
        ("take my stapler to Lee. On second thought, take it to Wang", "stapler", "mao", "wang"),
        ("bring my stapler to Lee. scratch that, take it to Wang", "stapler", "mao", "wang"),
    ],
)
def test_the_thing_of_the_replaced_request_is_kept(
    text: str, item: str, owner: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a stapler - no wait, some scissors",
        "bring me the stapler - no wait, bring me the scissors",
        "bring me a stapler - on second thoughts, some scissors",
    ],
)
def test_a_thing_said_in_the_correction_replaces_it(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("scissors", "mao")], frame


@pytest.mark.parametrize(
    "text",
    [
        "print my report - actually, never mind",
        "print my report - on second thoughts, never mind",
        "bring me a stapler. on second thoughts, don't bother",
    ],
)
def test_a_withdrawal_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame


def test_a_later_part_said_again_keeps_the_earlier_part() -> None:
    frame = _frame("print my report and take it to Lee - sorry, take it to Wang")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "mao", "wang")]
