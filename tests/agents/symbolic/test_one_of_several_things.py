"""One of a colleague's things named by a word for a kind ("could you bring me one of Kofi's
tools?" where Kofi has a track pump, a multitool and tyre levers) asks which: the word was
read as the one thing whose name it heads ("bike tool") and the multitool was fetched
(round 242). The answer names the thing. A word that is the thing's own name, or a colleague
with one thing of that kind, reads as before."""

from __future__ import annotations

import pytest

from helpers.reading import answered_reader, frame_reader
from helpers.tool_wall import tool_wall

_frame = frame_reader(tool_wall, "lin")
_answered = answered_reader(tool_wall, "lin")


@pytest.mark.parametrize(
    "text",
    [
        "Could you bring me one of Kofi's tools?",
        "can u grab one of kofi's tools for me",
        "need one of Kofi's tools asap",
    ],
)
def test_one_of_several_things_of_a_kind_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question == (
        "Kofi Mensah has several things: do you mean the track pump, the multitool or the "
        "tyre levers?"
    ), frame


@pytest.mark.parametrize(
    ("answer", "item"),
    [("the pump", "track_pump"), ("tyre levers pls", "tyre_levers"), ("multitool", "multitool")],
)
def test_the_answer_names_the_thing(answer: str, item: str) -> None:
    frame = _answered("Could you bring me one of Kofi's tools?", [answer])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "kofi", "lin")
    ], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Could you bring me one of Kofi's multitools?", "kofi"),  # the thing's own name
        ("Could you bring me one of Edda's tools?", "edda"),  # Edda has one such thing
        ("bring me Kofi's bike tool", "kofi"),
    ],
)
def test_a_name_or_a_single_thing_reads_as_before(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "multitool", owner, "lin")
    ], frame


@pytest.mark.parametrize("answer", ["the stapler", "dunno"])
def test_an_answer_naming_none_of_them_keeps_the_question(answer: str) -> None:
    frame = _answered("Could you bring me one of Kofi's tools?", [answer])
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Kofi Mensah has several things"), frame
