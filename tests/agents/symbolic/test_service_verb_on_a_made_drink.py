"""A service's verb said of a thing the service cannot take (fix213b class 4): "shred my tea" in
an office whose shredder takes notices and whose kitchen makes tea was read as making a tea,
the verb dropped. A service verb whose object is a thing the office makes from nothing (a
drink), and that no service of that verb takes or makes, is declined in one line ("I can't
shred a tea."), nothing made (``screen.wrong_input``)."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.parser import InstructionParser
from helpers.hostel import hostel


def _hostel(text: str) -> tuple[list[tuple[str, str | None]], str | None]:
    frame = InstructionParser(hostel()).parse(text, "hamid")
    return [(t.kind, t.item) for t in frame.tasks], frame.decline


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("shred my tea", "I can't shred a tea."),
        ("could you shred Bea's tea", "I can't shred a tea."),
        ("laminate the hot chocolate", "I can't laminate a hot chocolate."),
    ],
)
def test_hostel_the_drink_is_not_made(text: str, said: str) -> None:
    assert _hostel(text) == ([], said)


@pytest.mark.parametrize(
    ("text", "said"),
    [("heat my coffee", "I can't heat a coffee."), ("warm my coffee", "I can't warm a coffee.")],
)
def test_default_the_drink_is_not_made(text: str, said: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.decline == said


def test_neighbour_a_making_verb_makes() -> None:
    # "print" makes printouts: a verb of making, left to the readings as before
    frame = parser("default").parse("print my coffee", "lee")
    assert frame.decline is None


@pytest.mark.parametrize("text", ["brew me a tea", "make me a tea", "bring me a tea"])
def test_neighbour_the_drink_asked_for_is_made(text: str) -> None:
    assert _hostel(text) == ([("produce", "tea")], None)


def test_neighbour_the_service_s_own_input_is_served() -> None:
    tasks, decline = _hostel("shred my notice")
    assert decline is None and [item for _, item in tasks] == ["notice"]


def test_neighbour_a_paper_made_from_a_file_is_no_drink() -> None:
    # the shredder's own answer, not this one: a printout is a paper
    assert _hostel("shred my printout") == (
        [],
        "Sorry, I can't shred a printout here: I can only shred notices.",
    )
