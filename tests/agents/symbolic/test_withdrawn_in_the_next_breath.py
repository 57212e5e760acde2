"""A request withdrawn in the next breath (round 201's class): "get me a coffee... actually
don't worry, Sun's doing a round" drops the coffee and moves nothing (on main the bare "don't
worry" was no withdrawal, and the coffee was made and handed over); the reason after it only
explains. A withdrawal whose object the office does not have ("actually forget about the
biscuits, not hungry anymore") is words too, with its verbless reason (on main: asked what
to do). A withdrawal that names what the request can go without ("get me a coffee, and don't
worry about the sugar") withdraws no request: the coffee is still made."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "get me a coffee... actually don't worry, Sun's doing a round",
        "get me a coffee. don't worry, Sun's doing a round",
        "get me a snack, actually don't worry, not hungry",
        "get me a water. actually don't bother, Wang's just brought me one over",
    ],
)
def test_default_withdrawn_request_moves_nothing(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped that request" in frame.decline, frame


def test_harbour_withdrawn_request_moves_nothing() -> None:
    frame = _HARBOUR("get me a tea... actually don't worry, Mark's doing a round")
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped that request" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "actually forget about the biscuits, not hungry anymore",
        "never mind the cake, full already",
    ],
)
@pytest.mark.parametrize("frame_of", [_DEFAULT, _HARBOUR])
def test_withdrawal_of_a_thing_the_office_lacks_asks_nothing(
    text: str, frame_of: ReadFrame
) -> None:
    frame = frame_of(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped that request" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        # what the request goes without: the request stands
        ("get me a coffee, and don't worry about the sugar", "coffee", None),
        ("get me a coffee, don't worry about the milk", "coffee", None),
        # must not change: a leading "don't worry if ...", a new request after a withdrawal
        ("don't worry if Wang is busy, bring me her stapler later", "stapler", "wang"),
        ("actually never mind the coffee, bring me a water instead", "water", None),
        ("don't worry, bring me a water instead", "water", None),
    ],
)
def test_default_request_beside_a_withdrawal_word_stands(
    text: str, item: str, owner: str | None
) -> None:
    frame = _DEFAULT(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [(item, owner)], frame


@pytest.mark.parametrize(
    "text",
    [
        # a withdrawal after a stop, or with "actually", is second thoughts on the request
        "get me a coffee... don't worry about the biscuits",
        "get me a coffee. actually forget about the biscuits, not hungry",
        "get me a coffee. actually never mind the coffee",
        "print my file. actually scratch the printout",
    ],
)
def test_default_second_thoughts_withdraw_the_request(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_default_correction_head_is_no_detail() -> None:
    """ "no wait sorry, a pen": the head corrects what was just asked (and "sorry" names no
    thing), never read as what the request goes without; the pen replaces the stapler, which
    "can wait" (before, the chain "no wait sorry" was a withdrawal and both were fetched)."""
    frame = _DEFAULT("can you bring me a stapler, no wait sorry, a pen. the stapler can wait")
    said = {e.words: e.meaning for e in frame.evidence}
    assert "what the request may go without, context only" not in said.values(), frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "pen")], frame
