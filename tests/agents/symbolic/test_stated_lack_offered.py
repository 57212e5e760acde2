"""The speaker's own lack of a thing the office keeps for anyone, said with no request ("I'm
out on a job in twenty minutes and I haven't got a hi-vis vest", blind round 50's class; its
own sentences were never read), is met with an offer ("Shall I bring you one?") and the thing
comes on a yes; it was only noted. Nothing moves on the statement alone; a lack said of home
or beside the speaker's own plan to get more, and a statement with no lack, stay words."""

from __future__ import annotations

import pytest
from _offices import parser

from helpers.reading import answered_reader, frame_reader
from helpers.survey_hut import survey_hut

_frame = frame_reader(survey_hut, "okafor")
_answered = answered_reader(survey_hut, "okafor")


@pytest.mark.parametrize(
    "text",
    [
        "I'm out on a job in twenty minutes and I haven't got a hi-vis vest.",
        "I don't have a hi-vis vest and I'm on site in ten minutes",
        "heading out to the yard now, I've got no vest",
        "I haven't got a vest. Leaving in 5",
        "I do not have a hi-vis vest",
    ],
)
def test_a_stated_lack_of_a_supply_is_offered(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and "Shall I bring you one?" in frame.question, frame
    assert "stores" in frame.question and "_" not in frame.question, frame


def test_the_offer_brings_it_on_a_yes() -> None:
    text = "I'm out on a job in twenty minutes and I haven't got a hi-vis vest."
    frame = _answered(text, ["yes please"])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "vest", "okafor")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "I haven't got a vest, I'll grab one on the way",
        "I haven't got a hi-vis vest at home",
        "no hi-vis vest at home lol, will buy one on the way back",
        "out of vests at home lol, will buy some on the way back",
        "my clipboard is on my desk",
        # a thing the office keeps for nobody: no offer of another's
        "I haven't got a clipboard",
    ],
)
def test_no_lack_of_a_supply_moves_nothing_and_offers_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is None or "Shall I" not in frame.question, frame


def test_a_request_beside_the_lack_is_read_as_before() -> None:
    frame = _frame("I haven't got a vest, can you bring me Miles's clipboard")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "clipboard", "miles", "okafor")
    ], frame


def test_a_lack_of_what_a_cupboard_hands_out_is_offered() -> None:
    # harbour's stationery cupboard hands out notepads (a product made from nothing)
    text = "I'm heading into a meeting in five minutes and I haven't got a notepad."
    frame = parser("harbour").parse(text, "may")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "stationery cupboard" in frame.question and "Shall I get you one?" in frame.question
    answered = parser("harbour").parse_with_answers(text, "may", ["yes"])
    assert [(t.item, t.recipient) for t in answered.tasks] == [("notepad", "may")], answered


@pytest.mark.parametrize(
    "text",
    [
        "my stapler is on my desk",
        "out of paper at home lol, will buy some on the way back",
        "I don't have a pen, I'll borrow Chen's",
    ],
)
def test_the_default_offices_statements_stay_words(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame
