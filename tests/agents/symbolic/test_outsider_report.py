"""An outsider named bare ("Dad at reception", "Mum on the phone", "courier") reporting
something before a request is context: the report's pronouns are theirs, no colleague is asked
for (fix121a class 3). A colleague's report ("Wang says his stapler is broken, bring him
mine") binds "him" to the colleague, and a relayed request ("..., says could you ...") is read
as a request."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (
            _lin,
            "Dad at reception says his son's lost his pen - could you bring me a pen?",
            "pen",
            "lin",
        ),
        (_lin, "Dad says his pen ran out - could you bring me a pen?", "pen", "lin"),
        (
            _lin,
            "Mum at reception says her son's lost his pen - could you bring me a pen?",
            "pen",
            "lin",
        ),
        (
            _lin,
            "Mum on the phone says her daughter's lost her pen - could you bring me a pen?",
            "pen",
            "lin",
        ),
        (
            _lin,
            "the courier at the door says his van's blocked in, can you bring me a stapler?",
            "stapler",
            "lin",
        ),
        (
            _may,
            "Dad at reception said his son lost his ruler. Could you bring me a ruler?",
            "ruler",
            "may",
        ),
        (
            _may,
            "Driver at the gate says his calculator died - could you bring me a calculator?",
            "calculator",
            "may",
        ),
    ],
)
def test_an_outsiders_report_is_context(read: ReadFrame, text: str, item: str, who: str) -> None:
    frame = read(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, who)
    ], frame


def test_a_colleagues_report_binds_his_to_the_colleague() -> None:
    frame = _lin("Wang says his stapler is broken, bring him mine")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "lin", "wang")
    ], frame


def test_a_harbour_colleague_named_by_a_word_is_no_outsider() -> None:
    frame = _may("Mark says his ruler snapped, bring him mine")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", "may", "mark")
    ], frame


def test_a_relayed_request_is_still_asked_about() -> None:
    # "you" inside the report: a request passed on, not told; who "him" is stays asked
    frame = _lin("Dad says could you bring him a pen")
    assert frame.tasks == [] and frame.question is not None and "him" in frame.question, frame
