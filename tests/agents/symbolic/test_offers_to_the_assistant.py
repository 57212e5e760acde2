"""An offer made to the assistant is no request (reading/offers.py): "would you like a
ruler?", "fancy a coffee?", "can I get you a tea?" were read as the speaker asking for the
thing and fetched or made it for them; a message most likely meant for a colleague moved the
robot. Now it is a question: answered, and met with "Shall I bring you one?", carried out
only on a yes. Wanting with an infinitive ("would you like to bring me a pen?") is a request
put politely, as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, answered_reader, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")
_harbour_answered = answered_reader(harbour_office, "rose")
_default_answered = answered_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "would you like a ruler?",
        "would you like a ruler",
        "do you want a calculator?",
        "fancy a highlighter?",
        "would you care for a tea?",
        "can I get you a tea?",
        "you want a notepad?",
    ],
)
def test_an_offer_on_harbour_moves_nothing_and_is_asked(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "do you want a stapler?",
        "fancy a coffee?",
        "want a coffee?",
        "shall I make you a coffee?",
        "would you like some water?",
    ],
)
def test_an_offer_on_the_default_office_moves_nothing_and_is_asked(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I" in frame.question


def test_a_yes_brings_it_and_a_no_does_nothing() -> None:
    yes = _harbour_answered("would you like a ruler?", ("yes please",))
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("transfer", "ruler", "rose")]
    assert _harbour_answered("would you like a ruler?", ("no",)).tasks == []
    coffee = _default_answered("fancy a coffee?", ("yes",))
    assert [(t.kind, t.item, t.recipient) for t in coffee.tasks] == [("produce", "coffee", "lee")]


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        (_harbour, "would you bring me a ruler?", "ruler", "rose"),
        (_harbour, "could I have a ruler?", "ruler", "rose"),
        (_harbour, "would you like to bring me a calculator?", "calculator", "rose"),
        (_default, "do you want to bring me a stapler?", "stapler", "lee"),
        (_default, "can I get you to bring me a pen?", "pen", "lee"),
        (_default, "would you make me a coffee?", "coffee", "lee"),
        (_default, "I would like a coffee", "coffee", "lee"),
    ],
)
def test_a_request_put_as_a_want_is_read_as_before(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame
