"""A team or place said after "from" by a short name (an acronym, a team's common name, one
word of a facility's name) is where the thing comes from, never a colleague to ask about
(round 160, class 5; ``reading.team_source``): a word of one facility's name is that
facility, a team the office does not list leaves any one of the thing, and a capitalised
name of nobody that is no team ("from Bob") is still asked about."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.reading import frame_reader, parser_for
from helpers.repro_room import repro_room

_repro = frame_reader(repro_room, "bram")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's analogues
        ("can you borrow a dev kit from QA for me?", ("transfer", "dev_kit", None, "bram")),
        ("grab a spare laptop from IT", ("transfer", "laptop", None, "bram")),
        # variants: a team the office does not list, by acronym or by its common name
        ("grab a stapler from HR", ("transfer", "stapler", None, "bram")),
        ("grab me a stapler from Finance", ("transfer", "stapler", None, "bram")),
        ("can you fetch me a stapler from Ops?", ("transfer", "stapler", None, "bram")),
    ],
)
def test_a_team_after_from_is_a_source(text: str, expected: tuple[str | None, ...]) -> None:
    frame = _repro(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [expected], frame


def test_a_word_of_one_facilitys_name_is_that_facility() -> None:
    p = parser_for(repro_room)
    readings = p.readings.read(p.lex.read("grab a dev kit from QA"), "bram")
    assert [(m.kind, m.ids) for m in readings.mentions][-1] == ("facility", ("qa_store",))


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        ("harbour", "may", "grab a ruler from HR", ("transfer", "ruler", None, "may")),
        (
            "harbour",
            "may",
            "can you borrow a calculator from IT for me?",
            ("transfer", "calculator", None, "may"),
        ),
        ("harbour", "may", "grab me a notepad from Supply", ("produce", "notepad", None, "may")),
        (
            "default",
            "zhou",
            "can you borrow a stapler from QA for me?",
            ("transfer", "stapler", None, "zhou"),
        ),
        ("default", "zhou", "grab me a stapler from Wang", ("transfer", "stapler", "wang", "zhou")),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, expected: tuple[str | None, ...]
) -> None:
    assert tasks_of(office, text, requester) == [expected]


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("repro", "bram", "grab a stapler from Bob"),
        ("harbour", "may", "grab a calculator from Kelly"),
    ],
)
def test_a_name_of_nobody_is_still_asked(office: str, requester: str, text: str) -> None:
    frame = _repro(text) if office == "repro" else parser(office).parse(text, requester)
    assert frame.tasks == [] and frame.question is not None
    assert "know anyone called" in frame.question
