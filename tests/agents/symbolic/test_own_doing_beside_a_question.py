"""The speaker's own doing said after a question about a thing of the office ("Is there a loupe
going spare? I want to check the maker's mark on a teapot.") is why the thing is asked for: what
it names (a teapot) is context, never a thing to fetch or decline (blind round 57's class; its
offices and sentences were never read). Alone, such a sentence is read as before."""

from __future__ import annotations

import pytest

from helpers.bursary import bursary
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(bursary, "ana")
_answered = answered_reader(bursary, "ana")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Is there a loupe going spare? I want to check the maker's mark on a teapot.", "loupe"),
        ("Is there a loupe going spare? I need to look at a teapot", "loupe"),
        ("does anyone have a stopwatch? I have to time a relay", "stopwatch"),
        ("got a torch? I'd like to look under the boiler", "torch"),
        ("any torch going spare? we need to check under the boiler", "torch"),
    ],
)
def test_the_question_stands_and_the_doing_is_context(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert frame.question is not None and "Shall I bring you one?" in frame.question, frame
    taken = _answered(text, ["yes please"])
    assert [(t.item, t.recipient) for t in taken.tasks] == [(item, "ana")], taken


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can I have a torch? I would like to look under the boiler", "torch"),
        ("can I get a loupe? I want to check the maker's mark on a teapot", "loupe"),
    ],
)
def test_a_request_with_the_wish_of_ones_own_doing(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "ana")], frame


def test_the_doing_alone_still_names_what_is_missing() -> None:
    frame = _frame("I want to check the maker's mark on a teapot.")
    assert frame.tasks == [] and frame.decline is not None and "teapot" in frame.decline, frame


def test_a_wish_for_a_thing_is_still_a_request() -> None:
    frame = _frame("I'd like to borrow a torch")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("torch", "ana")], frame
