"""A send-out's place said only as someone's kind of place ("courier my report back to his
school", "fax it to her office") names no place the service can send to: which school, and
where? The place is asked (``reading.role_destination``), never sent as said; a place with a name,
a number or an address, or an organisation said by its kind ("the county tax office"), is
read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.sim.requester import Wish, answer
from helpers.dataset_offices import default_office_that_sends_out


def _parser() -> InstructionParser:
    return InstructionParser(
        default_office_that_sends_out(
            "courier", "courier", "courier", "the name and address of the school or place"
        )
    )


@pytest.mark.parametrize(
    "text",
    [
        "please courier my report back to his school",
        "courier my document to her office pls",
        "can you courier my document to their head office",
    ],
)
def test_the_place_is_asked(text: str) -> None:
    frame = _parser().parse(text, "lin")
    assert not frame.tasks, frame
    assert frame.question is not None, frame  # where, or whose ("her": nobody named)


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        (
            "courier my document to St Anne's School, 4 Elm Road, Leeds",
            "St Anne's School, 4 Elm Road, Leeds",
        ),
        ("courier my document to the county tax office", "the county tax office"),
        ("courier my document to his school, Hill Primary, 2 Kiln Lane", None),
    ],
)
def test_a_place_said_is_sent_to(text: str, destination: str | None) -> None:
    frame = _parser().parse(text, "lin")
    if destination is None:  # a name after it: the place is said, whatever its exact words
        assert frame.tasks and frame.tasks[0].destination, frame
    else:
        assert [t.destination for t in frame.tasks] == [destination], frame


def test_the_requester_does_not_take_a_statement_for_options() -> None:
    """The simulated requester answers the place they wrote; the office's own "or" in what its
    courier asks for ("the school or place") offers no options to choose from."""
    office = default_office_that_sends_out(
        "courier", "courier", "courier", "the name and address of the school or place"
    )
    wish = Wish.from_words(office, "lin", "courier my report to Hill Primary please")
    question = (
        "Where should I courier it to? Please give me the name and address of the school or place."
    )
    assert answer(office, wish, question) == "To Hill Primary."
