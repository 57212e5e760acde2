"""A vague word for a thing the speaker says they left somewhere ("bring me the thing I left
at the printer", "grab the stuff I left in the meeting room") is their own thing there, not
said which: the reader asks what it is, in the place's own words (blind rounds 61-62's class:
"Sorry, there is no left at the printer that I know of"). A thing named ("my stapler I left
in the meeting room") and a vague word with nothing left anywhere are read as before
(``helpers.courier_room``)."""

from __future__ import annotations

import pytest

from helpers.courier_room import courier_room
from helpers.reading import frame_reader, parser_for

_frame = frame_reader(courier_room, "bjorn")


@pytest.mark.parametrize(
    ("text", "question"),
    [
        (
            "can you bring me the thing I left at the print room",
            "What did you leave at the print room?",
        ),
        ("grab the stuff I left in the meeting room", "What did you leave in the meeting room?"),
        (
            "bring me the bits I forgot in the post room please",
            "What did you leave in the post room?",
        ),
        ("can you bring me the thing I left at the printer", "What did you leave at the printer?"),
        (
            "grab the stuff that I left behind in the meeting room for me",
            "What did you leave in the meeting room?",
        ),
    ],
)
def test_what_was_left_is_asked(text: str, question: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question == question, frame


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me my stapler I left in the meeting room",
        "bring me the thing",
        "bring me the stapler from the print room",
    ],
)
def test_a_thing_named_or_nothing_left_is_read_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None or not frame.question.startswith("What did you leave"), frame


def test_the_answer_names_the_thing() -> None:
    frame = parser_for(courier_room).parse_with_answers(
        "can you bring me the thing I left at the print room", "bjorn", ["my stapler"]
    )
    assert frame.decline is None and "left" not in (frame.question or ""), frame
