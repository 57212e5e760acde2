"""An idiom of time said right before an imperative with no comma ("when you get a sec grab me
a notepad from the supply cupboard") is politeness: the imperative is the request (fix210b
class 1: it was read as a question, "As far as I know the stationery cupboard ... is in
service", or without the place as an offer, "Shall I get you one?"). Questions after the
idiom, a question opened by "when", and a condition on the robot's whereabouts read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "rose")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "when you get a sec grab me a notepad from the supply cupboard",
        "when you get a sec grab me a notepad",
        "when you get a minute fetch me a notepad from the stationery cupboard",
        "whenever you get a chance bring me a notepad from the cupboard",
        "when you have a moment get me a notepad",
        # neighbours already read as asked
        "when you get a sec, grab me a notepad from the supply cupboard",
        "when you're at the cupboard, grab me a notepad",
        "grab me a notepad from the supply cupboard",
    ],
)
def test_the_imperative_after_the_idiom_is_the_request(text: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.recipient) for t in frame.tasks] == [("notepad", "rose")]


@pytest.mark.parametrize(
    "text",
    [
        "when you get a sec grab me a pen from the print room",
        "when you get a moment bring me a stapler",
        "whenever you're free bring me a stapler",
    ],
)
def test_the_fetch_after_the_idiom_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "lee")]


@pytest.mark.parametrize(
    "text", ["when is the printer free?", "when you get a sec, is the printer working?"]
)
def test_a_question_stays_a_question(text: str) -> None:
    frame = _harbour(text)
    assert not frame.tasks, frame
    assert "in service" in (frame.decline or ""), frame
