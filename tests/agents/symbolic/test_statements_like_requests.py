"""Sentences that only look like requests. The speaker's own going with its subject dropped
("Off to a site meeting in a min", "Heading to the bank", "Popping out to the shop") is
context, the request the other sentence (the going was once read as an errand outside, or
asked about). A past form with its particle opening a sentence that says it is done ("Drew
up the report last night, finally") is the speaker's own doing, even where the past form is a
colleague's name: told in words, nothing moves. Near misses keep their readings: the name
said to the person ("Drew, can you ..."), a request beside the going."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader
from helpers.verb_names import verb_names


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_default, "lee")
_named = frame_reader(verb_names, "ines")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Morning! Off to a site meeting in a min. Could you find me a stapler? Ta", "stapler"),
        ("Popping out to the bank in a bit, can you bring me a stapler", "stapler"),
        ("Off to the post office now. Please bring me a pen", "pen"),
        ("heading to the bank, can you bring me a pen", "pen"),
        ("Just off to a site meeting. Could you bring me a stapler?", "stapler"),
        ("Nipping out to the shop. Could you bring me the scissors?", "scissors"),
    ],
)
def test_the_speakers_own_going_is_context(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "lee")]


def test_a_request_after_going_to_lunch_still_runs() -> None:
    frame = _frame("Off to lunch - bring my cup to Zhang please")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "cup", "lee", "zhang")
    ], frame


def test_going_alone_moves_nothing() -> None:
    frame = _frame("Off to a meeting, back at 3")
    assert frame.tasks == [], frame


@pytest.mark.parametrize(
    "text",
    [
        "Drew up the report for Castle Street last night, finally",
        "Drew up the survey for Mill Road yesterday",
        "Drew out the plans for Castle Street earlier",
        "Marked up the report for Hill Lane this morning",
        "Chased up the report for Castle Street last week",
    ],
)
def test_a_names_past_form_with_a_done_time_is_a_statement(text: str) -> None:
    frame = _named(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_a_request_beside_it_still_runs() -> None:
    frame = _named(
        "Drew up the survey for Castle Street yesterday, can you bring me a tape measure"
    )
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "tape", "ines")]


@pytest.mark.parametrize(
    "text",
    [
        "Drew can you bring me the tape measure",
        "Mark, could you bring me the tape measure please",
    ],
)
def test_the_name_said_to_its_person_is_still_a_name(text: str) -> None:
    frame = _named(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "tape")], frame
